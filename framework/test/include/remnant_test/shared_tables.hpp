#pragma once
// The shared EOS tables (../shared/eos beside the project) for tests: their paths, and a skip with
// a message when one is missing -- never a silent pass.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace remnant::test {

inline std::string shared_eos(const std::string& name) {
#ifdef REMNANT_SHARED_EOS_DIR
  return std::string(REMNANT_SHARED_EOS_DIR) + "/" + name;
#else
  return "../shared/eos/" + name;
#endif
}

}  // namespace remnant::test

#define REQUIRE_TABLE(path)                                                                \
  do {                                                                                     \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "EOS table not found: " << (path); \
  } while (0)
