#include "checkpoint_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "remnant/error.hpp"
#include "xdmf.hpp"

namespace remnant::io {

namespace fs = std::filesystem;

std::string checkpoint_path(const std::string& dir, std::int64_t iteration) {
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint.it%010lld.h5", static_cast<long long>(iteration));
  return dir + "/" + name;
}

std::vector<std::string> list_checkpoints(const std::string& dir) {
  std::vector<std::pair<std::int64_t, std::string>> found;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return {};
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::int64_t it = iteration_of(e.path().filename().string(), "checkpoint", "h5");
    if (it >= 0) found.emplace_back(it, e.path().string());
  }
  std::sort(found.rbegin(), found.rend());
  std::vector<std::string> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

namespace {
void fsync_path(const std::string& path, bool directory) {
  const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) throw RunError("IO: cannot open " + path + " to sync it: " + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  // Some file systems cannot sync directories (EINVAL): the rename is still atomic there.
  if (rc != 0 && !(directory && err == EINVAL)) throw RunError("IO: fsync " + path + " failed: " + std::strerror(err));
}
}  // namespace

void commit_file(const std::string& tmp, const std::string& final_path) {
  fsync_path(tmp, false);
  std::error_code ec;
  fs::rename(tmp, final_path, ec);
  if (ec) throw RunError("IO: cannot rename " + tmp + " to " + final_path + ": " + ec.message());
  fsync_path(fs::path(final_path).parent_path().string(), true);
}

std::vector<std::string> prune_checkpoints(const std::string& dir, int keep, const std::string& except) {
  std::vector<std::string> deleted;
  const auto all = list_checkpoints(dir);
  for (std::size_t i = static_cast<std::size_t>(std::max(keep, 1)); i < all.size(); ++i) {
    std::error_code ec;
    if (fs::remove(all[i], ec)) deleted.push_back(all[i]);
  }
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("checkpoint.it", 0) == 0 && e.path().extension() == ".tmp" && e.path().string() != except) {
      std::error_code ec2;
      if (fs::remove(e.path(), ec2)) deleted.push_back(e.path().string());
    }
  }
  return deleted;
}

}  // namespace remnant::io
