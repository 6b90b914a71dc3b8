// MSH 4.1 ASCII: entities carry the physical groups; nodes and elements come in blocks, one block
// per entity.
#include <map>
#include <sstream>

#include "gmsh_element_types.hpp"
#include "msh_raw.hpp"

namespace styk::gmsh {
namespace {

using EntityPhysicals = std::map<std::pair<int, int>, std::vector<int>>;

long long count_of(MshTokens& tokens, const char* what) {
  const long long n = tokens.next_integer(what);
  if (n < 0) tokens.fail(std::string(what) + " is negative");
  return n;
}

void read_entities(MshTokens& tokens, EntityPhysicals& physicals) {
  long long counts[4];
  for (long long& c : counts) c = count_of(tokens, "an entity count");
  for (int dim = 0; dim < 4; ++dim) {
    for (long long i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(tokens.next_integer("an entity tag"));
      // A point has its position, the others their bounding box.
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) tokens.next_real("an entity coordinate");
      std::vector<int>& groups = physicals[{dim, tag}];
      const long long group_count = count_of(tokens, "the number of physical tags");
      for (long long g = 0; g < group_count; ++g)
        groups.push_back(static_cast<int>(tokens.next_integer("a physical tag")));
      if (dim == 0) continue;
      const long long bounding = count_of(tokens, "the number of bounding entities");
      for (long long b = 0; b < bounding; ++b) tokens.next_integer("a bounding entity tag");
    }
  }
  if (tokens.next("$EndEntities") != "$EndEntities")
    tokens.fail("$Entities holds more than its counts say");
}

void read_nodes(MshTokens& tokens, RawMesh& mesh) {
  const long long blocks = count_of(tokens, "the number of node blocks");
  count_of(tokens, "the number of nodes");
  tokens.next_integer("the smallest node tag");
  tokens.next_integer("the largest node tag");
  for (long long b = 0; b < blocks; ++b) {
    const long long dim = tokens.next_integer("a node block's entity dimension");
    tokens.next_integer("a node block's entity tag");
    const long long parametric = tokens.next_integer("a node block's parametric flag");
    const long long count = count_of(tokens, "a node block's node count");
    const std::size_t first = mesh.nodes.size();
    for (long long i = 0; i < count; ++i) {
      RawNode node;
      node.tag = tokens.next_integer("a node tag");
      mesh.nodes.push_back(node);
    }
    for (long long i = 0; i < count; ++i) {
      RawNode& node = mesh.nodes[first + i];
      for (double& c : node.x) c = tokens.next_real("a node coordinate");
      node.line = tokens.line();
      // Parametric coordinates follow on curves (u), surfaces (u, v) and volumes (u, v, w).
      if (parametric != 0)
        for (long long p = 0; p < dim; ++p) tokens.next_real("a parametric coordinate");
    }
  }
  if (tokens.next("$EndNodes") != "$EndNodes") tokens.fail("$Nodes holds more than its counts say");
}

void read_element_line(MshTokens& tokens, const GmshType* type, RawElement& element) {
  element.tag = tokens.next_integer("an element tag");
  element.line = tokens.line();
  std::istringstream rest(tokens.rest_of_line());
  std::string token;
  while (rest >> token) {
    try {
      std::size_t used = 0;
      element.nodes.push_back(std::stoll(token, &used));
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      tokens.fail("a node tag must be an integer, not '" + token + "'");
    }
  }
  if (type && static_cast<int>(element.nodes.size()) != type->nodes)
    tokens.fail(std::string("a ") + type->name + " needs " + std::to_string(type->nodes) +
                " node tags, this line has " + std::to_string(element.nodes.size()));
}

void read_elements(MshTokens& tokens, const EntityPhysicals& physicals, RawMesh& mesh) {
  const long long blocks = count_of(tokens, "the number of element blocks");
  count_of(tokens, "the number of elements");
  tokens.next_integer("the smallest element tag");
  tokens.next_integer("the largest element tag");
  for (long long b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(tokens.next_integer("an element block's entity dimension"));
    const int entity = static_cast<int>(tokens.next_integer("an element block's entity tag"));
    const int type_number = static_cast<int>(tokens.next_integer("an element block's type"));
    const long long count = count_of(tokens, "an element block's element count");
    tokens.rest_of_line();
    const GmshType* type = find_gmsh_type(type_number);
    const auto groups = physicals.find({dim, entity});
    for (long long i = 0; i < count; ++i) {
      RawElement element;
      element.type = type_number;
      if (groups != physicals.end()) element.physicals = groups->second;
      read_element_line(tokens, type, element);
      mesh.elements.push_back(std::move(element));
    }
  }
  if (tokens.next("$EndElements") != "$EndElements")
    tokens.fail("$Elements holds more than its counts say");
}

}  // namespace

void read_msh4(MshTokens& tokens, RawMesh& mesh) {
  EntityPhysicals physicals;
  std::string section;
  while (tokens.try_next(section)) {
    if (section == "$PhysicalNames")
      read_physical_names(tokens, mesh);
    else if (section == "$Entities")
      read_entities(tokens, physicals);
    else if (section == "$Nodes")
      read_nodes(tokens, mesh);
    else if (section == "$Elements")
      read_elements(tokens, physicals, mesh);
    else if (section == "$PartitionedEntities")
      tokens.fail(
          "a partitioned mesh ($PartitionedEntities) is not read: save the mesh whole "
          "(Mesh.PartitionSplitMeshFiles = 0, or without partitioning)");
    else if (section.rfind('$', 0) == 0 && section.rfind("$End", 0) != 0)
      skip_section(tokens, section);
    else
      tokens.fail("expected a section ($Entities, $Nodes, $Elements, ...), found '" + section +
                  "'");
  }
}

}  // namespace styk::gmsh
