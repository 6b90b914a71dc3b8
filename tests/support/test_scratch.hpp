// A scratch directory of the running test's own: ctest runs the cases of one executable as
// separate processes in parallel, so decks written under a shared directory with names that only
// depend on their content's parameters would be overwritten by another case mid-read.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace styk::test {

// STYK_BINARY_DIR/<area>/<suite>.<test> (parameterised names with '/' flattened), created.
inline std::filesystem::path test_scratch_dir(const std::string& area) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
  for (char& c : test)
    if (c == '/') c = '_';
  const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / area / test;
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace styk::test
