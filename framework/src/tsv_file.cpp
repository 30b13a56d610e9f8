#include "remnant/tsv_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "remnant/error.hpp"

namespace remnant {

std::int64_t trim_tsv_file(const std::string& path, std::int64_t last) {
  std::ifstream in(path);
  if (!in) throw RunError("cannot read " + path);
  std::ostringstream kept;
  std::string line;
  std::int64_t dropped = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      kept << line << "\n";
      continue;
    }
    // A row cut short by a crash has no trailing newline or fewer columns: drop it too.
    long long it = 0;
    const bool complete = !in.eof() && std::sscanf(line.c_str(), "%lld", &it) == 1 && line.find('\t') != std::string::npos;
    if (complete && it <= last) kept << line << "\n";
    else ++dropped;
  }
  in.close();
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << kept.str();
    if (!out) throw RunError("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
  return dropped;
}

void start_or_resume_tsv_file(const Context& ctx, const std::string& path, const std::string& header, RowTime rows) {
  if (ctx.recovered() && std::filesystem::exists(path)) {
    const std::int64_t last = ctx.recovered_iteration() - (rows == RowTime::before_step ? 1 : 0);
    const std::int64_t dropped = trim_tsv_file(path, last);
    if (dropped > 0)
      ctx.info("dropped " + std::to_string(dropped) + " rows of " + path + " after the recovered iteration " +
               std::to_string(ctx.recovered_iteration()));
    return;
  }
  std::ofstream out(path, std::ios::trunc);
  out << header;
  if (!out) throw RunError("cannot write " + path);
}

}  // namespace remnant
