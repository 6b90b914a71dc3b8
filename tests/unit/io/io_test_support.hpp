// Shared fixtures of the styk_io tests: a scratch directory, a unit-cube model and its deck.
#pragma once

#include <string>

#include "styk/core/model.hpp"

namespace styk::io_test {

// An empty directory under the build tree (recreated on every call).
std::string fresh_dir(const std::string& name);
std::string read_text(const std::string& path);
bool file_exists(const std::string& path);

// Unit cube, one C3D8 (id 1), nodes 1-8 in Abaqus order; node sets NALL, FIX (z = 0) and TOP
// (z = 1), element set EALL. Steps and output requests are left to the test.
Model unit_cube();

// The same cube as a CalculiX deck: E = 210000, nu = 0.3, bottom face held (statically
// determinate), four 100 N loads in +z on the top face. Step 1 prints U and RF of NALL and S, E of
// EALL; step 2 adds -50 N at node 5 and prints U of TOP and S of EALL.
std::string unit_cube_deck();

}  // namespace styk::io_test
