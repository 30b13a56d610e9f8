#pragma once
// A checksum of a whole checkpoint file, kept in the file's HDF5 user block (the first
// kFileSealBytes, which HDF5 never reads): recovery checks it before HDF5 parses anything, because
// the HDF5 library can crash, not just fail, on a damaged object header. Files without a seal
// (written before it existed) are read as before, protected by the metadata and data checksums.
#include <string>

namespace remnant::io {

inline constexpr unsigned kFileSealBytes = 512;  // the HDF5 user block size (a power of 2, >= 512)

// Writes the seal of the bytes after the user block into the user block of `path`.
void seal_file(const std::string& path);

// "" when the seal matches or the file has none; else why the file is unusable.
std::string check_file_seal(const std::string& path);

}  // namespace remnant::io
