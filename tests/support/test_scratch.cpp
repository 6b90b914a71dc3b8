#include "test_scratch.hpp"

#include <gtest/gtest.h>

namespace styk::test {

std::filesystem::path fresh_scratch_dir(const std::filesystem::path& relative) {
  const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / relative;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path test_scratch_dir(const std::string& area) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
  for (char& c : test)
    if (c == '/') c = '_';
  const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / area / test;
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace styk::test
