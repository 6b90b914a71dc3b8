// A Gmsh mesh as the file states it, before any mapping to Styk: nodes by tag, elements with
// their Gmsh type, and the physical groups each element belongs to.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "msh_tokens.hpp"
#include "styk/core/model.hpp"

namespace styk::gmsh {

struct RawNode {
  Id tag = 0;
  Vec3 x{};
  int line = 0;
};

struct RawElement {
  Id tag = 0;
  int type = 0;                // Gmsh element type number
  std::vector<int> physicals;  // physical tags (of the element's dimension)
  std::vector<Id> nodes;       // node tags in Gmsh's order
  int line = 0;
};

struct RawMesh {
  std::string format;  // "2.2" or "4.1"
  std::vector<RawNode> nodes;
  std::vector<RawElement> elements;
  std::map<std::pair<int, int>, std::string> physical_names;  // (dim, tag) -> name
};

// Reads the sections after $MeshFormat; `tokens` stands after the format line.
void read_msh2(MshTokens& tokens, RawMesh& mesh);
void read_msh4(MshTokens& tokens, RawMesh& mesh);

// $PhysicalNames (both versions): `tokens` stands after the section's opening line.
void read_physical_names(MshTokens& tokens, RawMesh& mesh);

// Skips an unknown section up to its $End line (the format asks readers to ignore them).
void skip_section(MshTokens& tokens, const std::string& name);

}  // namespace styk::gmsh
