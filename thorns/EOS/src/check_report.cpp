#include "EOS/check_report.hpp"

#include <sstream>

namespace remnant::eos {

std::string CheckIssue::str() const {
  std::ostringstream o;
  o << (level == Level::warning ? "warning: " : "note: ") << file;
  if (!dataset.empty()) o << " [" << dataset << "]";
  o << ": " << message;
  if (count) o << " (" << count << " points)";
  return o.str();
}

std::size_t CheckReport::warnings() const {
  std::size_t n = 0;
  for (const auto& i : issues) n += i.level == CheckIssue::Level::warning;
  return n;
}

const CheckIssue* CheckReport::find(const std::string& dataset) const {
  for (const auto& i : issues)
    if (i.level == CheckIssue::Level::warning && i.dataset == dataset) return &i;
  return nullptr;
}

std::string CheckReport::str() const {
  std::ostringstream o;
  for (const auto& i : issues) o << i.str() << "\n";
  return o.str();
}

}  // namespace remnant::eos
