// CompOSE ASCII file sets: eos.nb, eos.t, eos.yq (first line lowest index, second line highest
// index, then one value per line) and eos.thermo (first line m_n m_p lepton-flag, then rows
// iT inb iYq Q1..Q7 Nadd [additional quantities]).
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "compose_common.hpp"

namespace remnant::eos {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TableError(path, "", "cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Reads numbers one at a time from a text buffer, naming the file and line on errors.
class NumberReader {
 public:
  NumberReader(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
    p_ = text_.c_str();
  }
  bool at_end() {
    skip_space();
    return *p_ == '\0';
  }
  double next(const char* what) {
    skip_space();
    if (*p_ == '\0') fail(std::string("unexpected end of file, expected ") + what);
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(p_, &end);
    if (end == p_) fail(std::string("expected a number (") + what + ")");
    p_ = end;
    return v;
  }
  long next_int(const char* what) {
    double v = next(what);
    if (v != double(long(v))) fail(std::string("expected an integer (") + what + ")");
    return long(v);
  }
  int line() const { return line_; }
  [[noreturn]] void fail(const std::string& msg) const {
    throw TableError(path_, "", "line " + std::to_string(line_) + ": " + msg);
  }
  void skip_line() {
    while (*p_ && *p_ != '\n') ++p_;
  }

 private:
  void skip_space() {
    while (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n') {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }
  std::string path_, text_;
  const char* p_;
  int line_ = 1;
};

struct AxisFile {
  long lo = 0;
  std::vector<double> v;
};

AxisFile read_axis(const std::string& path) {
  NumberReader r(path, slurp(path));
  AxisFile a;
  a.lo = r.next_int("lowest index");
  long hi = r.next_int("highest index");
  if (hi < a.lo) r.fail("highest index is below the lowest index");
  for (long i = a.lo; i <= hi; ++i) a.v.push_back(r.next("axis value"));
  if (!r.at_end()) r.fail("more values than the index range " + std::to_string(a.lo) + ".." + std::to_string(hi));
  return a;
}

}  // namespace

RawTable read_compose_ascii(const std::string& dir, const ReadOptions& opts) {
  detail::ComposeGrid g;
  g.file = dir;
  g.thermo_dataset = "eos.thermo";
  AxisFile nb = read_axis(dir + "/eos.nb"), t = read_axis(dir + "/eos.t"), yq = read_axis(dir + "/eos.yq");
  g.nb = nb.v;
  g.T = t.v;
  g.yq = yq.v;
  const std::size_t nr = g.nb.size(), nt = g.T.size(), ny = g.yq.size(), n = nr * nt * ny;
  for (auto& q : g.Q) q.assign(n, 0.0);
  std::vector<unsigned char> seen(n, 0);

  const std::string path = dir + "/eos.thermo";
  NumberReader r(path, slurp(path));
  g.m_n = r.next("m_n");
  g.m_p = r.next("m_p");
  r.next("lepton flag");
  std::size_t rows = 0;
  while (!r.at_end()) {
    long it = r.next_int("iT") - t.lo, ir = r.next_int("inb") - nb.lo, iy = r.next_int("iYq") - yq.lo;
    if (it < 0 || it >= long(nt) || ir < 0 || ir >= long(nr) || iy < 0 || iy >= long(ny))
      r.fail("grid index outside eos.nb/eos.t/eos.yq ranges");
    const std::size_t i = (std::size_t(iy) * nt + it) * nr + ir;
    if (seen[i]) r.fail("grid point given twice");
    seen[i] = 1;
    for (int k = 0; k < 7; ++k) g.Q[k][i] = r.next("Q1..Q7");
    const long nadd = r.next_int("number of additional quantities");
    for (long k = 0; k < nadd; ++k) r.next("additional quantity");
    ++rows;
  }
  if (rows != n) {
    for (std::size_t i = 0; i < n; ++i)
      if (!seen[i]) {
        const std::size_t ir = i % nr, it = (i / nr) % nt, iy = i / (nr * nt);
        throw TableError(path, "eos.thermo", std::to_string(n - rows) + " of " + std::to_string(n) +
                                                 " grid points missing, first at (iT, inb, iYq) = (" +
                                                 std::to_string(it + t.lo) + ", " + std::to_string(ir + nb.lo) +
                                                 ", " + std::to_string(iy + yq.lo) + ")");
      }
  }
  return detail::compose_to_raw(std::move(g), opts, "CompOSE ASCII");
}

}  // namespace remnant::eos
