#pragma once
// Error types. InputError is for anything the user wrote (parfiles, thorn.yaml, command line):
// its message names file:line:col and, where possible, the allowed values.
#include <stdexcept>
#include <string>

namespace remnant {

struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based; 0 when unknown
  int column = 0;
  std::string str() const {
    if (file.empty()) return "<unknown>";
    if (line <= 0) return file;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
  }
};

class InputError : public std::runtime_error {
 public:
  InputError(const SourceLocation& where, const std::string& what)
      : std::runtime_error(where.str() + ": error: " + what), where_(where) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

// A failure while running (a thorn function, I/O). The driver aborts every rank.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace remnant
