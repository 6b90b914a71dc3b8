#include "styk/mesher/interface.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher {

const Interface& split_interface(Mesh& mesh, const std::string& body_a, const std::string& name) {
  const auto set = mesh.element_sets.find(to_upper(body_a));
  if (set == mesh.element_sets.end() || set->second.empty())
    throw std::invalid_argument("split_interface: no element set named " + to_upper(body_a));
  std::vector<char> in_a(mesh.elements.size(), 0);
  for (int e : set->second) in_a[e] = 1;
  if (set->second.size() == mesh.elements.size())
    throw std::invalid_argument("split_interface: set " + to_upper(body_a) + " is the whole mesh");

  // Facing faces, found by their corner nodes before the split.
  std::map<std::array<int, 4>, std::vector<FaceRef>> by_corners;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    for (int f = 0; f < 6; ++f) {
      std::array<int, 4> key{};
      const std::vector<int> local = face_corner_nodes(f);
      for (int i = 0; i < 4; ++i) key[i] = mesh.elements[e].nodes[local[i]];
      std::sort(key.begin(), key.end());
      by_corners[key].push_back({e, f});
    }
  std::vector<FaceRef> faces_a, faces_b;
  for (const auto& [key, faces] : by_corners) {
    if (faces.size() != 2) continue;
    const bool a0 = in_a[faces[0].element], a1 = in_a[faces[1].element];
    if (a0 == a1) continue;
    faces_a.push_back(a0 ? faces[0] : faces[1]);
    faces_b.push_back(a0 ? faces[1] : faces[0]);
  }
  if (faces_a.empty())
    throw std::invalid_argument("split_interface: set " + to_upper(body_a) +
                                " shares no face with the rest of the mesh");

  std::vector<char> used_a(mesh.nodes.size(), 0);
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    if (in_a[e])
      for (int n : mesh.elements[e].nodes) used_a[n] = 1;
  std::vector<int> copy(mesh.nodes.size(), -1);
  Interface interface;
  interface.name = to_upper(name);
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e) {
    if (in_a[e]) continue;
    for (int& n : mesh.elements[e].nodes) {
      if (!used_a[n]) continue;
      if (copy[n] < 0) {
        copy[n] = mesh.add_node(mesh.nodes[n]);
        interface.pairs.emplace_back(n, copy[n]);
      }
      n = copy[n];
    }
  }
  std::sort(interface.pairs.begin(), interface.pairs.end());
  interface.surface_a = interface.name + "_A";
  interface.surface_b = interface.name + "_B";
  mesh.add_to_surface(interface.surface_a, faces_a);
  mesh.add_to_surface(interface.surface_b, faces_b);
  mesh.interfaces.push_back(std::move(interface));
  return mesh.interfaces.back();
}

}  // namespace styk::mesher
