// From the file's own terms (RawMesh) to a Model: the elements of the highest dimension in
// CalculiX's node order, physical groups as sets.
#include "styk/gmsh/gmsh_import.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "gmsh_element_types.hpp"
#include "msh_raw.hpp"

namespace styk {
namespace {

using gmsh::GmshType;
using gmsh::MshTokens;
using gmsh::RawElement;
using gmsh::RawMesh;

RawMesh read_raw(const std::string& path) {
  MshTokens tokens(path);
  if (tokens.next("$MeshFormat") != "$MeshFormat")
    tokens.fail("not a Gmsh mesh: the file must begin with $MeshFormat");
  RawMesh mesh;
  mesh.format = tokens.next("the format version");
  const long long file_type = tokens.next_integer("the file type");
  tokens.next_integer("the data size");
  if (file_type != 0)
    tokens.fail("a binary .msh file is not read: save it as ASCII (Mesh.Binary = 0)");
  if (tokens.next("$EndMeshFormat") != "$EndMeshFormat")
    tokens.fail("$MeshFormat must hold one line: version, file type, data size");
  if (mesh.format == "2.2" || mesh.format == "2.1" || mesh.format == "2")
    gmsh::read_msh2(tokens, mesh);
  else if (mesh.format == "4.1")
    gmsh::read_msh4(tokens, mesh);
  else
    throw InputError({path, 2}, "MSH format version " + mesh.format +
                                    " is not read (versions read: 2.2 and 4.1; Gmsh writes them "
                                    "with Mesh.MshFileVersion = 2.2 or 4.1)");
  if (mesh.elements.empty()) tokens.fail("the mesh holds no elements");
  return mesh;
}

// MSH 2.2 repeats an element once per physical group it belongs to, under the same tag: the
// repeats become one element in every group. A tag used for a different element is an error.
void merge_repeated_elements(const std::string& path, RawMesh& mesh) {
  std::map<Id, std::size_t> first_by_tag;
  std::vector<RawElement> merged;
  for (RawElement& element : mesh.elements) {
    const auto [found, fresh] = first_by_tag.emplace(element.tag, merged.size());
    if (fresh) {
      merged.push_back(std::move(element));
      continue;
    }
    RawElement& first = merged[found->second];
    if (first.type != element.type || first.nodes != element.nodes)
      throw InputError({path, element.line}, "element tag " + std::to_string(element.tag) +
                                                 " was used at line " + std::to_string(first.line) +
                                                 " for another element");
    first.physicals.insert(first.physicals.end(), element.physicals.begin(),
                           element.physicals.end());
  }
  mesh.elements = std::move(merged);
}

int dimension_of(const RawElement& element, const std::string& path) {
  const GmshType* type = gmsh::find_gmsh_type(element.type);
  if (!type)
    throw InputError({path, element.line}, "Gmsh element type " + std::to_string(element.type) +
                                               " is not one Styk knows");
  return type->dimension;
}

// A physical name as a CalculiX set name.
std::string set_name(const RawMesh& mesh, int dim, int tag) {
  const auto found = mesh.physical_names.find({dim, tag});
  if (found == mesh.physical_names.end() || found->second.empty())
    return "PHYSICAL" + std::to_string(dim) + "D_" + std::to_string(tag);
  std::string name = to_upper(found->second);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return name;
}

class ModelBuilder {
 public:
  ModelBuilder(const std::string& path, const RawMesh& mesh, const GmshImportOptions& options)
      : path_(path), mesh_(mesh), options_(options) {
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      if (!node_by_tag_.emplace(mesh.nodes[i].tag, static_cast<int>(i)).second)
        throw InputError({path, mesh.nodes[i].line},
                         "node tag " + std::to_string(mesh.nodes[i].tag) + " appears twice");
    }
    for (const RawElement& element : mesh.elements)
      top_dimension_ = std::max(top_dimension_, dimension_of(element, path));
  }

  Model build(GmshImportSummary& summary) {
    model_.source = path_;
    // No *HEADING: the deck is meant for *INCLUDE, and ccx refuses a second *HEADING. write_inp()
    // names the mesh file in its first comment line.
    summary.format = mesh_.format;
    summary.dimension = top_dimension_;
    std::vector<std::pair<const RawElement*, gmsh::StykElementMapping>> kept;
    for (const RawElement& element : mesh_.elements) {
      if (dimension_of(element, path_) == top_dimension_)
        kept.emplace_back(&element, mapping_of(element));
      else
        ++summary.lower_dimension_elements;
    }
    add_used_nodes(kept, summary);
    for (const auto& [element, mapping] : kept) add_element(*element, mapping, summary);
    add_sets();
    return std::move(model_);
  }

 private:
  gmsh::StykElementMapping mapping_of(const RawElement& element) const {
    const GmshType& type = *gmsh::find_gmsh_type(element.type);
    std::string why;
    gmsh::StykElementMapping mapping = gmsh::styk_mapping(type, options_, why);
    if (mapping.type.empty())
      throw InputError({path_, element.line}, std::string("Gmsh element type ") +
                                                  std::to_string(type.number) + " (" + type.name +
                                                  ") is not imported: " + why);
    return mapping;
  }

  int raw_node(const RawElement& element, Id tag) const {
    const auto found = node_by_tag_.find(tag);
    if (found == node_by_tag_.end())
      throw InputError({path_, element.line}, "element " + std::to_string(element.tag) +
                                                  " names node " + std::to_string(tag) +
                                                  ", which $Nodes does not define");
    return found->second;
  }

  // Only the nodes of imported elements become nodes, in the file's order.
  void add_used_nodes(
      const std::vector<std::pair<const RawElement*, gmsh::StykElementMapping>>& kept,
      GmshImportSummary& summary) {
    std::vector<char> used(mesh_.nodes.size(), 0);
    for (const auto& entry : kept)
      for (Id tag : entry.first->nodes) used[raw_node(*entry.first, tag)] = 1;
    node_index_.assign(mesh_.nodes.size(), -1);
    for (std::size_t i = 0; i < mesh_.nodes.size(); ++i) {
      if (!used[i]) {
        ++summary.unused_nodes;
        continue;
      }
      const gmsh::RawNode& node = mesh_.nodes[i];
      node_index_[i] = model_.add_node(node.tag, node.x, {path_, node.line});
    }
  }

  void add_element(const RawElement& element, const gmsh::StykElementMapping& mapping,
                   GmshImportSummary& summary) {
    std::vector<int> nodes;
    for (int g : mapping.gmsh_index)
      nodes.push_back(node_index_[raw_node(element, element.nodes[g])]);
    const int index = model_.add_element(element.tag, mapping.type, nodes, {path_, element.line});
    if (std::find(summary.element_types.begin(), summary.element_types.end(), mapping.type) ==
        summary.element_types.end())
      summary.element_types.push_back(mapping.type);
    for (int physical : element.physicals)
      element_groups_[{top_dimension_, physical}].push_back(index);
  }

  void add_sets() {
    std::map<std::pair<int, int>, std::set<int>> node_groups;
    for (const RawElement& element : mesh_.elements) {
      const int dim = dimension_of(element, path_);
      for (int physical : element.physicals)
        for (Id tag : element.nodes) {
          const int index = node_index_[raw_node(element, tag)];
          if (index >= 0) node_groups[{dim, physical}].insert(index);
        }
    }
    for (const auto& [key, nodes] : node_groups) {
      NodeSet& set = named_nset(set_name(mesh_, key.first, key.second));
      set.nodes.insert(set.nodes.end(), nodes.begin(), nodes.end());
      std::sort(set.nodes.begin(), set.nodes.end());
      set.nodes.erase(std::unique(set.nodes.begin(), set.nodes.end()), set.nodes.end());
    }
    for (const auto& [key, elements] : element_groups_) {
      ElementSet& set = model_.elsets[set_name(mesh_, key.first, key.second)];
      set.name = set_name(mesh_, key.first, key.second);
      set.where = {path_, 0};
      set.elements.insert(set.elements.end(), elements.begin(), elements.end());
      std::sort(set.elements.begin(), set.elements.end());
      set.elements.erase(std::unique(set.elements.begin(), set.elements.end()), set.elements.end());
    }
    add_whole_model_set("NALL", "EALL");
  }

  NodeSet& named_nset(const std::string& name) {
    NodeSet& set = model_.nsets[name];
    set.name = name;
    set.where = {path_, 0};
    return set;
  }

  void add_whole_model_set(const std::string& nset, const std::string& elset) {
    if (model_.nsets.count(nset) || model_.elsets.count(elset))
      throw InputError({path_, 0}, "a physical group is named " + nset + " or " + elset +
                                       ", the names import gives the whole mesh: rename it");
    NodeSet& nodes = named_nset(nset);
    for (int n = 0; n < model_.node_count(); ++n) nodes.nodes.push_back(n);
    ElementSet& elements = model_.elsets[elset];
    elements.name = elset;
    elements.where = {path_, 0};
    for (int e = 0; e < model_.element_count(); ++e) elements.elements.push_back(e);
  }

  const std::string& path_;
  const RawMesh& mesh_;
  const GmshImportOptions& options_;
  int top_dimension_ = 0;
  std::map<Id, int> node_by_tag_;
  std::vector<int> node_index_;  // raw node -> model node, -1 when unused
  std::map<std::pair<int, int>, std::vector<int>> element_groups_;
  Model model_;
};

}  // namespace

int gmsh_mesh_dimension(const std::string& path) {
  const RawMesh mesh = read_raw(path);
  int dimension = 0;
  for (const RawElement& element : mesh.elements)
    dimension = std::max(dimension, dimension_of(element, path));
  return dimension;
}

Model import_gmsh(const std::string& path, const GmshImportOptions& options,
                  GmshImportSummary* summary) {
  RawMesh mesh = read_raw(path);
  merge_repeated_elements(path, mesh);
  GmshImportSummary local;
  Model model = ModelBuilder(path, mesh, options).build(summary ? *summary : local);
  return model;
}

}  // namespace styk
