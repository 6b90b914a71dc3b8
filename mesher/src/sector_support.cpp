#include "sector_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "builder_support.hpp"
#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher::detail {
namespace {

// The angle of x about z measured from the sector's middle, in (-pi, pi].
double angle_from_middle(const Vec3& x, double middle) {
  const double c = std::cos(middle), s = std::sin(middle);
  return std::atan2(-s * x[0] + c * x[1], c * x[0] + s * x[1]);
}

bool contains(const std::vector<int>& sorted, int value) {
  return std::binary_search(sorted.begin(), sorted.end(), value);
}

}  // namespace

bool SectorBoundary::is_slave(int node) const { return contains(slave, node); }
bool SectorBoundary::is_axis(int node) const { return contains(axis, node); }

SectorBoundary sector_boundary(const Mesh& mesh, int sectors, double tolerance) {
  SectorBoundary out;
  out.sectors = sectors;
  std::vector<int> slave = mesh.surface_nodes(kCyclicSlaveFaces);
  std::vector<int> master = mesh.surface_nodes(kCyclicMasterFaces);
  const auto on_axis = [&](int node) {
    return std::hypot(mesh.nodes[node][0], mesh.nodes[node][1]) <= tolerance;
  };
  for (const std::vector<int>* side : {&slave, &master})
    for (int node : *side)
      if (on_axis(node)) out.axis.push_back(node);
  std::sort(out.axis.begin(), out.axis.end());
  out.axis.erase(std::unique(out.axis.begin(), out.axis.end()), out.axis.end());
  for (int node : slave)
    if (!on_axis(node)) out.slave.push_back(node);
  for (int node : master)
    if (!on_axis(node)) out.master.push_back(node);
  return out;
}

void cut_sector(Mesh& mesh, int sectors, double theta0) {
  const double half = kPi / sectors, middle = theta0 + half;
  const auto centroid = [&](const std::vector<int>& nodes) {
    Vec3 c{0, 0, 0};
    for (int node : nodes)
      for (int d = 0; d < 3; ++d) c[d] += mesh.nodes[node][d] / nodes.size();
    return c;
  };
  std::vector<char> keep(mesh.elements.size(), 0);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const double phi = angle_from_middle(centroid(mesh.elements[e].nodes), middle);
    keep[e] = phi >= -half && phi < half;
  }
  // Faces between a kept element and one left out, by their sorted corner nodes.
  std::map<std::array<int, 4>, std::vector<FaceRef>> by_corners;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int f = 0; f < 6; ++f) {
      std::array<int, 4> key;
      const std::vector<int> corners = face_corner_nodes(f);
      for (int i = 0; i < 4; ++i) key[i] = mesh.elements[e].nodes[corners[i]];
      std::sort(key.begin(), key.end());
      by_corners[key].push_back({static_cast<int>(e), f});
    }
  std::vector<FaceRef> slave, master;
  for (const auto& [corners, faces] : by_corners) {
    if (faces.size() != 2 || keep[faces[0].element] == keep[faces[1].element]) continue;
    const FaceRef inside = keep[faces[0].element] ? faces[0] : faces[1];
    const std::vector<int> c(corners.begin(), corners.end());
    (angle_from_middle(centroid(c), middle) < 0 ? slave : master).push_back(inside);
  }
  if (slave.empty() || master.empty())
    throw std::invalid_argument("the sector has no boundary towards its neighbours");
  std::vector<int> new_index(mesh.elements.size(), -1);
  std::vector<MeshElement> kept;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    if (keep[e]) {
      new_index[e] = static_cast<int>(kept.size());
      kept.push_back(mesh.elements[e]);
    }
  if (kept.size() * sectors != mesh.elements.size())
    throw std::invalid_argument("the mesh does not repeat itself " + std::to_string(sectors) +
                                " times about the z axis (" + std::to_string(kept.size()) + " of " +
                                std::to_string(mesh.elements.size()) + " elements in the sector)");
  mesh.elements = std::move(kept);
  for (auto& [name, members] : mesh.element_sets) {
    std::vector<int> renumbered;
    for (int e : members)
      if (new_index[e] >= 0) renumbered.push_back(new_index[e]);
    members = std::move(renumbered);
  }
  mesh.surfaces[kCyclicSlaveFaces] = slave;
  mesh.surfaces[kCyclicMasterFaces] = master;
  for (auto& [name, faces] : mesh.surfaces) {
    std::vector<FaceRef> renumbered;
    for (const FaceRef& f : faces)
      if (new_index[f.element] >= 0) renumbered.push_back({new_index[f.element], f.face});
    std::sort(renumbered.begin(), renumbered.end());
    faces = std::move(renumbered);
  }
  mesh.remove_unused_nodes();
}

void mirror_about_xz(Mesh& mesh) {
  const int node_count = static_cast<int>(mesh.nodes.size());
  for (int n = 0; n < node_count; ++n)
    mesh.add_node({mesh.nodes[n][0], -mesh.nodes[n][1], mesh.nodes[n][2]});
  const int element_count = static_cast<int>(mesh.elements.size());
  for (int e = 0; e < element_count; ++e) {
    const MeshElement element = mesh.elements[e];
    const std::vector<Vec3>& natural = natural_nodes(element.type);
    std::vector<int> nodes(element.nodes.size());
    for (std::size_t k = 0; k < natural.size(); ++k) {
      const Vec3 reflected{natural[k][0], -natural[k][1], natural[k][2]};
      std::size_t source = natural.size();
      for (std::size_t j = 0; j < natural.size(); ++j)
        if (std::abs(natural[j][0] - reflected[0]) + std::abs(natural[j][1] - reflected[1]) +
                std::abs(natural[j][2] - reflected[2]) <
            1e-12)
          source = j;
      if (source == natural.size())
        throw std::invalid_argument("mirror_about_xz: " + element.type +
                                    " has no node at a reflected natural point");
      nodes[k] = element.nodes[source] + node_count;
    }
    mesh.add_element(element.type, nodes);
  }
  for (auto& [name, members] : mesh.element_sets) {
    const std::size_t count = members.size();
    for (std::size_t i = 0; i < count; ++i) members.push_back(members[i] + element_count);
    std::sort(members.begin(), members.end());
  }
  for (auto& [name, faces] : mesh.surfaces) {
    const std::size_t count = faces.size();
    for (std::size_t i = 0; i < count; ++i) {
      const FaceAxis a = face_axis(faces[i].face);
      faces.push_back(
          {faces[i].element + element_count, face_index(a.axis, a.axis == 1 ? -a.value : a.value)});
    }
    std::sort(faces.begin(), faces.end());
  }
}

std::vector<FaceRef> faces_on_half_plane(const Mesh& mesh, double theta, double tolerance) {
  const double c = std::cos(theta), s = std::sin(theta);
  std::vector<FaceRef> out;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    for (int f = 0; f < 6; ++f) {
      bool on = true;
      for (int k : face_corner_nodes(f)) {
        const Vec3& x = mesh.nodes[mesh.elements[e].nodes[k]];
        on = on && std::abs(-s * x[0] + c * x[1]) <= tolerance && c * x[0] + s * x[1] >= -tolerance;
      }
      if (on) out.push_back({static_cast<int>(e), f});
    }
  return out;
}

void add_cyclic_symmetry(Model& model, const SectorBoundary& boundary) {
  for (const char* name : {"CYCLIC_SLAVE", "CYCLIC_MASTER"}) {
    Surface surface;
    surface.name = name;
    surface.kind = Surface::Kind::Nodes;
    const std::vector<int>& side =
        std::string(name) == "CYCLIC_SLAVE" ? boundary.slave : boundary.master;
    surface.nodes = side;
    surface.nodes.insert(surface.nodes.end(), boundary.axis.begin(), boundary.axis.end());
    std::sort(surface.nodes.begin(), surface.nodes.end());
    model.surfaces[name] = std::move(surface);
  }
  CyclicSymmetry tie;
  tie.tie = "CYCLIC";
  tie.slave = "CYCLIC_SLAVE";
  tie.master = "CYCLIC_MASTER";
  tie.sectors = boundary.sectors;
  tie.a = {0, 0, 0};
  tie.b = {0, 0, 1};
  model.cyclic_symmetries.push_back(tie);
}

void fix_in_sector(Model& model, const SectorBoundary& boundary, const std::vector<int>& nodes,
                   std::initializer_list<int> dofs) {
  for (int node : nodes) {
    if (boundary.is_slave(node)) continue;
    for (int dof : dofs) {
      if (boundary.is_axis(node) && dof != 3) continue;
      model.boundaries.push_back({node, dof, 0.0, {}});
    }
  }
}

}  // namespace styk::mesher::detail
