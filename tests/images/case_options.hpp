// The OPTION=VALUE words of tests/images/cases.txt, applied to RenderOptions.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "styk/render/render_job.hpp"

namespace styk::render_test {

struct ImageCase {
  std::string name;
  std::string scene;
  std::vector<std::string> options;  // OPTION=VALUE
};

// gtest prints a case by its manifest line.
void PrintTo(const ImageCase& c, std::ostream* out);

// Throws std::invalid_argument on an unknown option.
render::RenderOptions options_for(const ImageCase& c, int width, int height);

// Reads the manifest; comment lines start with '#'.
std::vector<ImageCase> read_cases(const std::string& path);

}  // namespace styk::render_test
