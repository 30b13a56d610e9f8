#pragma once
// Checkpoint file names and their life cycle on disk: <dir>/checkpoint.it<10 digits>.h5, written
// as <name>.tmp, made durable (fsync) and renamed when complete; the newest K are kept.
#include <cstdint>
#include <string>
#include <vector>

namespace remnant::io {

std::string checkpoint_path(const std::string& dir, std::int64_t iteration);
// Complete checkpoint files in dir (never *.tmp), newest iteration first.
std::vector<std::string> list_checkpoints(const std::string& dir);
// fsync(path), rename(path, final), fsync(directory): the rename is atomic, so a crash leaves
// either the old state or the whole new file. Throws RunError.
void commit_file(const std::string& tmp, const std::string& final_path);
// "" when `dir` exists or can be created and a file can be created in it; else why not.
std::string writable_folder_problem(const std::string& dir);
// Deletes all but the newest `keep` checkpoints up to iteration `current` (the one just written)
// and any leftover *.tmp; returns the deleted names. Files named after a later iteration are left
// alone: they are ones recovery rejected (or foreign copies), and must not count as the newest.
std::vector<std::string> prune_checkpoints(const std::string& dir, int keep, std::int64_t current);

}  // namespace remnant::io
