#include "styk/mesher/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace styk::mesher {
namespace {

template <typename T>
void merge_sorted(std::vector<T>& into, const std::vector<T>& more) {
  into.insert(into.end(), more.begin(), more.end());
  std::sort(into.begin(), into.end());
  into.erase(std::unique(into.begin(), into.end()), into.end());
}

}  // namespace

void Mesh::add_to_node_set(const std::string& name, const std::vector<int>& members) {
  merge_sorted(node_sets[to_upper(name)], members);
}

void Mesh::add_to_element_set(const std::string& name, const std::vector<int>& members) {
  merge_sorted(element_sets[to_upper(name)], members);
}

void Mesh::add_to_surface(const std::string& name, const std::vector<FaceRef>& faces) {
  merge_sorted(surfaces[to_upper(name)], faces);
}

std::vector<int> Mesh::surface_nodes(const std::string& name) const {
  std::vector<int> out;
  const auto it = surfaces.find(to_upper(name));
  if (it == surfaces.end()) return out;
  for (const FaceRef& f : it->second) {
    const MeshElement& e = elements[f.element];
    const auto layout = faces_of_type.find(e.type);
    if (layout == faces_of_type.end() || f.face < 0 ||
        f.face >= static_cast<int>(layout->second.size()))
      throw std::logic_error("mesh: surface " + to_upper(name) + " names face S" +
                             std::to_string(f.face + 1) + " of element " +
                             std::to_string(f.element + 1) + " (" + e.type +
                             "), whose faces the mesh was not told");
    for (int local : layout->second[f.face]) out.push_back(e.nodes[local]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void Mesh::renumber_nodes(const std::vector<int>& old_to_new, int new_count) {
  std::vector<Vec3> moved(new_count);
  for (std::size_t i = 0; i < old_to_new.size(); ++i)
    if (old_to_new[i] >= 0) moved[old_to_new[i]] = nodes[i];
  nodes = std::move(moved);
  for (MeshElement& e : elements)
    for (int& n : e.nodes) n = old_to_new[n];
  for (auto& [name, set] : node_sets) {
    std::vector<int> kept;
    for (int n : set)
      if (old_to_new[n] >= 0) kept.push_back(old_to_new[n]);
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    set = std::move(kept);
  }
  // A pair that loses a node is dropped, as a removed node leaves its sets: a C3D28 conversion
  // removes the C3D20 bottom mid-edge nodes, and a kept -1 would index old_to_new[-1] on the
  // next renumbering.
  for (Interface& i : interfaces) {
    std::vector<std::pair<int, int>> kept;
    for (const auto& [a, b] : i.pairs)
      if (old_to_new[a] >= 0 && old_to_new[b] >= 0) kept.emplace_back(old_to_new[a], old_to_new[b]);
    i.pairs = std::move(kept);
  }
}

int Mesh::remove_unused_nodes() {
  std::vector<char> used(nodes.size(), 0);
  for (const MeshElement& e : elements)
    for (int n : e.nodes) used[n] = 1;
  std::vector<int> old_to_new(nodes.size(), -1);
  int count = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (used[i]) old_to_new[i] = count++;
  const int removed = static_cast<int>(nodes.size()) - count;
  if (removed > 0) renumber_nodes(old_to_new, count);
  return removed;
}

double Mesh::size() const {
  if (nodes.empty()) return 0.0;
  Vec3 lo = nodes[0], hi = nodes[0];
  for (const Vec3& x : nodes)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

Model to_model(const Mesh& mesh, const std::string& source) {
  Model model;
  model.source = source;
  const SourceLoc here{source, 0};
  model.node_ids.reserve(mesh.nodes.size());
  model.coords.reserve(mesh.nodes.size());
  // Round-off residue of trigonometric maps (cos 90 deg = 6e-17) becomes an exact zero: it is
  // noise, and CalculiX reads coordinates in 20-character fields, too narrow for 1.2246e-16 at
  // full precision.
  const double tiny = 1e-13 * mesh.size();
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    Vec3 x = mesh.nodes[n];
    for (double& c : x)
      if (std::abs(c) < tiny) c = 0.0;
    model.add_node(static_cast<Id>(n + 1), x, here);
  }
  model.elements.reserve(mesh.elements.size());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    model.add_element(static_cast<Id>(e + 1), mesh.elements[e].type, mesh.elements[e].nodes, here);
  for (const auto& [name, nodes] : mesh.node_sets) {
    if (nodes.empty()) continue;
    NodeSet& set = model.nsets[name];
    set.name = name;
    set.nodes = nodes;
  }
  for (const auto& [name, elements] : mesh.element_sets) {
    if (elements.empty()) continue;
    ElementSet& set = model.elsets[name];
    set.name = name;
    set.elements = elements;
  }
  return model;
}

}  // namespace styk::mesher
