#include "file_seal.hpp"

#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

#include "remnant/error.hpp"

namespace remnant::io {

namespace {

constexpr char kMagic[] = "remnant-file-seal fnv64 ";

// FNV-1a over 8-byte words (and the trailing bytes), as the data checksums: GB/s, not cryptographic.
std::uint64_t digest_after_user_block(std::ifstream& in, std::uint64_t& bytes) {
  std::uint64_t h = 14695981039346656037ull;
  std::vector<char> buf(1 << 20);
  in.seekg(kFileSealBytes);
  bytes = 0;
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    std::size_t i = 0;
    for (; i + 8 <= got; i += 8) {
      std::uint64_t w;
      std::memcpy(&w, buf.data() + i, 8);
      h = (h ^ w) * 1099511628211ull;
      h ^= h >> 29;
    }
    for (; i < got; ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
    bytes += got;
  }
  return h ^ bytes;
}

}  // namespace

void seal_file(const std::string& path) {
  std::uint64_t bytes = 0, h = 0;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RunError("IO: cannot reopen " + path + " to seal it");
    h = digest_after_user_block(in, bytes);
  }
  char seal[kFileSealBytes] = {};
  std::snprintf(seal, sizeof seal, "%s%016" PRIx64 " %" PRIu64 "\n", kMagic, h, bytes);
  std::fstream out(path, std::ios::binary | std::ios::in | std::ios::out);
  out.seekp(0);
  out.write(seal, sizeof seal);
  if (!out) throw RunError("IO: cannot write the seal of " + path);
}

std::string check_file_seal(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "it cannot be read";
  char seal[kFileSealBytes] = {};
  in.read(seal, sizeof seal);
  if (in.gcount() != static_cast<std::streamsize>(sizeof seal) || std::strncmp(seal, kMagic, sizeof kMagic - 1) != 0)
    return "";  // no seal: an older file (or a damaged magic, which HDF5 never reads either)
  std::uint64_t want = 0, want_bytes = 0;
  if (std::sscanf(seal + sizeof kMagic - 1, "%16" SCNx64 " %" SCNu64, &want, &want_bytes) != 2)
    return "its file seal is unreadable";
  in.clear();
  std::uint64_t bytes = 0;
  const std::uint64_t got = digest_after_user_block(in, bytes);
  if (bytes != want_bytes)
    return "it has " + std::to_string(bytes + kFileSealBytes) + " bytes where its seal says " +
           std::to_string(want_bytes + kFileSealBytes) + " (truncated or extended)";
  if (got != want) return "its contents do not match the file seal (damaged on disk or in transfer)";
  return "";
}

}  // namespace remnant::io
