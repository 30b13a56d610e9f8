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

std::string writable_folder_problem(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create the folder (" + ec.message() + ")";
  if (!fs::is_directory(dir, ec)) return "it is not a folder";
  const std::string probe = dir + "/.remnant-write-test." + std::to_string(::getpid());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) return std::string("cannot create a file in it (") + std::strerror(errno) + ")";
  const bool written = ::write(fd, "x", 1) == 1;
  const int err = errno;
  ::close(fd);
  ::unlink(probe.c_str());
  if (!written) return std::string("cannot write a file in it (") + std::strerror(err) + ")";
  return "";
}

std::vector<std::string> prune_checkpoints(const std::string& dir, int keep, std::int64_t current) {
  std::vector<std::string> deleted;
  std::size_t kept = 0;
  for (const auto& path : list_checkpoints(dir)) {
    if (iteration_of(fs::path(path).filename().string(), "checkpoint", "h5") > current) continue;
    if (kept++ < static_cast<std::size_t>(std::max(keep, 1))) continue;
    std::error_code ec;
    if (fs::remove(path, ec)) deleted.push_back(path);
  }
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("checkpoint.it", 0) == 0 && e.path().extension() == ".tmp") {
      std::error_code ec2;
      if (fs::remove(e.path(), ec2)) deleted.push_back(e.path().string());
    }
  }
  return deleted;
}

}  // namespace remnant::io
