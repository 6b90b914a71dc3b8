// The parts of the MSH format both versions share: $PhysicalNames and unknown sections.
#include "msh_raw.hpp"

namespace styk::gmsh {

void read_physical_names(MshTokens& tokens, RawMesh& mesh) {
  const long long count = tokens.next_integer("the number of physical names");
  if (count < 0) tokens.fail("the number of physical names is negative");
  for (long long i = 0; i < count; ++i) {
    const int dim = static_cast<int>(tokens.next_integer("a physical group's dimension"));
    const int tag = static_cast<int>(tokens.next_integer("a physical group's tag"));
    std::string name = tokens.rest_of_line();
    if (name.size() < 2 || name.front() != '"' || name.back() != '"')
      tokens.fail("a physical name must be written in double quotes");
    mesh.physical_names[{dim, tag}] = name.substr(1, name.size() - 2);
  }
  if (tokens.next("$EndPhysicalNames") != "$EndPhysicalNames")
    tokens.fail("$PhysicalNames holds more names than its count says");
}

void skip_section(MshTokens& tokens, const std::string& name) {
  const std::string end = "$End" + name.substr(1);
  std::string token;
  while (tokens.try_next(token)) {
    if (token == end) return;
    tokens.rest_of_line();
  }
  tokens.fail("section " + name + " has no " + end);
}

}  // namespace styk::gmsh
