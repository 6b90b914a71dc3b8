// MSH 2.2 ASCII: $Nodes with one node per line, $Elements with the physical group as the first
// tag of every element.
#include "gmsh_element_types.hpp"
#include "msh_raw.hpp"

namespace styk::gmsh {
namespace {

void read_nodes(MshTokens& tokens, RawMesh& mesh) {
  const long long count = tokens.next_integer("the number of nodes");
  if (count < 0) tokens.fail("the number of nodes is negative");
  for (long long i = 0; i < count; ++i) {
    RawNode node;
    node.tag = tokens.next_integer("a node tag");
    node.line = tokens.line();
    for (double& c : node.x) c = tokens.next_real("a node coordinate");
    mesh.nodes.push_back(node);
  }
  if (tokens.next("$EndNodes") != "$EndNodes")
    tokens.fail("$Nodes holds more nodes than its count says");
}

void read_elements(MshTokens& tokens, RawMesh& mesh) {
  const long long count = tokens.next_integer("the number of elements");
  if (count < 0) tokens.fail("the number of elements is negative");
  for (long long i = 0; i < count; ++i) {
    RawElement element;
    element.tag = tokens.next_integer("an element tag");
    element.line = tokens.line();
    element.type = static_cast<int>(tokens.next_integer("an element type"));
    const GmshType* type = find_gmsh_type(element.type);
    if (!type)
      tokens.fail("Gmsh element type " + std::to_string(element.type) +
                  " is not one Styk knows (it cannot tell how many nodes it has)");
    const long long tag_count = tokens.next_integer("the number of element tags");
    if (tag_count < 0) tokens.fail("the number of element tags is negative");
    for (long long t = 0; t < tag_count; ++t) {
      const long long tag = tokens.next_integer("an element tag");
      // The first tag is the physical group (0: none), the second the elementary entity.
      if (t == 0 && tag != 0) element.physicals.push_back(static_cast<int>(tag));
    }
    for (int n = 0; n < type->nodes; ++n)
      element.nodes.push_back(tokens.next_integer("a node tag"));
    mesh.elements.push_back(std::move(element));
  }
  if (tokens.next("$EndElements") != "$EndElements")
    tokens.fail("$Elements holds more elements than its count says");
}

}  // namespace

void read_msh2(MshTokens& tokens, RawMesh& mesh) {
  std::string section;
  while (tokens.try_next(section)) {
    if (section == "$PhysicalNames")
      read_physical_names(tokens, mesh);
    else if (section == "$Nodes")
      read_nodes(tokens, mesh);
    else if (section == "$Elements")
      read_elements(tokens, mesh);
    else if (section.rfind('$', 0) == 0 && section.rfind("$End", 0) != 0)
      skip_section(tokens, section);
    else
      tokens.fail("expected a section ($Nodes, $Elements, ...), found '" + section + "'");
  }
}

}  // namespace styk::gmsh
