#include "io_test_support.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/test_scratch.hpp"

namespace styk::io_test {

std::string fresh_dir(const std::string& name) {
  return test::fresh_scratch_dir(std::filesystem::path("tests/unit/io/scratch") / name).string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool file_exists(const std::string& path) { return std::filesystem::exists(path); }

Model unit_cube() {
  Model model;
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) model.add_node(i + 1, corners[i], {});
  model.add_element(1, "C3D8", {0, 1, 2, 3, 4, 5, 6, 7}, {});
  model.nsets["NALL"] = NodeSet{"NALL", {0, 1, 2, 3, 4, 5, 6, 7}, {}};
  model.nsets["FIX"] = NodeSet{"FIX", {0, 1, 2, 3}, {}};
  model.nsets["TOP"] = NodeSet{"TOP", {4, 5, 6, 7}, {}};
  model.elsets["EALL"] = ElementSet{"EALL", {0}, {}};
  return model;
}

std::string unit_cube_deck() {
  return R"(*HEADING
unit cube for the styk_io tests
*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=FIX
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
1, 1, 3
2, 2, 3
3, 3, 3
4, 1, 1
4, 3, 3
*CLOAD
5, 3, 100.
6, 3, 100.
7, 3, 100.
8, 3, 100.
*NODE PRINT, NSET=NALL
U, RF
*EL PRINT, ELSET=EALL
S, E
*END STEP
*STEP
*STATIC
0.5, 0.5
*CLOAD
5, 3, -50.
*NODE PRINT, NSET=TOP
U
*EL PRINT, ELSET=EALL
S
*END STEP
)";
}

}  // namespace styk::io_test
