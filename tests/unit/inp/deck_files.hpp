// Writing scratch decks for the reader tests into the build tree.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include "../../support/test_scratch.hpp"

namespace styk::test {

inline std::filesystem::path scratch_dir() { return test_scratch_dir("inp_test_decks"); }

// Writes `text` to scratch_dir()/name and returns the path.
inline std::string write_deck(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratch_dir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

inline std::string input_path(const std::string& relative) {
  return std::string(STYK_SOURCE_DIR) + "/tests/inputs/" + relative;
}

}  // namespace styk::test
