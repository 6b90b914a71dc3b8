#include "styk/mesher/convert.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <iterator>
#include <map>
#include <stdexcept>

#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher {
namespace {

using CornerKey = std::array<int, 4>;

std::string element_name(int e) { return "element " + std::to_string(e + 1); }

CornerKey corner_key(const MeshElement& element, int face) {
  CornerKey key{};
  const std::vector<int> local = face_corner_nodes(face);
  for (int i = 0; i < 4; ++i) key[i] = element.nodes[local[i]];
  std::sort(key.begin(), key.end());
  return key;
}

std::vector<int> all_of_type(const Mesh& mesh, const std::vector<int>& elements,
                             const std::string& type) {
  if (!elements.empty()) return elements;
  std::vector<int> out;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    if (mesh.elements[e].type == type) out.push_back(e);
  return out;
}

std::vector<Vec3> coords_of(const Mesh& mesh, const MeshElement& element) {
  std::vector<Vec3> x;
  for (int n : element.nodes) x.push_back(mesh.nodes[n]);
  return x;
}

// Renumbers C3D20 element e so that its face `face` becomes S1, and updates the face numbers of
// every surface that names e.
void reorient_to_bottom(Mesh& mesh, int e, int face) {
  if (face == 0) return;
  const CubeRotation R = rotation_to_bottom(face);
  MeshElement& element = mesh.elements[e];
  const std::vector<int> perm = rotated_numbering(element.type, R);
  std::vector<int> nodes(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k) nodes[k] = element.nodes[perm[k]];
  element.nodes = std::move(nodes);
  for (auto& [name, faces] : mesh.surfaces) {
    bool touched = false;
    for (FaceRef& f : faces)
      if (f.element == e) {
        f.face = rotated_face(R, f.face);
        touched = true;
      }
    if (touched) std::sort(faces.begin(), faces.end());
  }
}

// The surface's faces by element, checking one face per element and the element type.
std::map<int, int> layer_faces(const Mesh& mesh, const std::string& surface) {
  const auto it = mesh.surfaces.find(to_upper(surface));
  if (it == mesh.surfaces.end() || it->second.empty())
    throw std::invalid_argument("element conversion: no surface named " + to_upper(surface));
  std::map<int, int> layer;
  for (const FaceRef& f : it->second) {
    if (mesh.elements[f.element].type != "C3D20")
      throw std::invalid_argument("element conversion: " + element_name(f.element) + " is " +
                                  mesh.elements[f.element].type + ", not C3D20");
    if (!layer.emplace(f.element, f.face).second)
      throw std::invalid_argument("element conversion: " + element_name(f.element) +
                                  " has two faces on surface " + to_upper(surface));
  }
  return layer;
}

void set_surface_to_bottom(Mesh& mesh, const std::string& surface,
                           const std::map<int, int>& layer) {
  std::vector<FaceRef> faces;
  for (const auto& [e, f] : layer) faces.push_back({e, 0});
  mesh.surfaces[to_upper(surface)] = faces;
}

}  // namespace

void convert_to_c3d14(Mesh& mesh, const std::vector<int>& elements) {
  // Face-centre node order of C3D14: 9 S1, 10 S2, 11 S3, 12 S5, 13 S6, 14 S4.
  static constexpr int kFaceOrder[6] = {0, 1, 2, 4, 5, 3};
  std::map<CornerKey, int> centre;
  for (int e : all_of_type(mesh, elements, "C3D8")) {
    MeshElement& element = mesh.elements[e];
    if (element.type != "C3D8")
      throw std::invalid_argument("convert_to_c3d14: " + element_name(e) + " is " + element.type);
    for (int face : kFaceOrder) {
      const CornerKey key = corner_key(element, face);
      auto found = centre.find(key);
      if (found == centre.end()) {
        Vec3 x{0, 0, 0};
        for (int n : key)
          for (int d = 0; d < 3; ++d) x[d] += 0.25 * mesh.nodes[n][d];
        found = centre.emplace(key, mesh.add_node(x)).first;
      }
      element.nodes.push_back(found->second);
    }
    element.type = "C3D14";
  }
}

void convert_to_c3d20r(Mesh& mesh, const std::vector<int>& elements) {
  for (int e : all_of_type(mesh, elements, "C3D20")) {
    if (mesh.elements[e].type != "C3D20")
      throw std::invalid_argument("convert_to_c3d20r: " + element_name(e) + " is " +
                                  mesh.elements[e].type);
    mesh.elements[e].type = "C3D20R";
  }
}

void convert_to_c3d27(Mesh& mesh, const std::vector<int>& elements) {
  // Natural coordinates of the face centres S1..S6 (C3D27 nodes 21-26), then the centre (27).
  static const Vec3 kCentres[7] = {{0, 0, -1}, {0, 0, 1},  {0, -1, 0}, {1, 0, 0},
                                   {0, 1, 0},  {-1, 0, 0}, {0, 0, 0}};
  std::map<CornerKey, int> centre;
  for (int e : all_of_type(mesh, elements, "C3D20")) {
    if (mesh.elements[e].type != "C3D20")
      throw std::invalid_argument("convert_to_c3d27: " + element_name(e) + " is " +
                                  mesh.elements[e].type);
    const std::vector<Vec3> x = coords_of(mesh, mesh.elements[e]);
    std::vector<int> added;
    for (int face = 0; face < 6; ++face) {
      const CornerKey key = corner_key(mesh.elements[e], face);
      auto found = centre.find(key);
      if (found == centre.end())
        found = centre.emplace(key, mesh.add_node(map_point("C3D20", x, kCentres[face]))).first;
      added.push_back(found->second);
    }
    added.push_back(mesh.add_node(map_point("C3D20", x, kCentres[6])));
    MeshElement& element = mesh.elements[e];
    element.nodes.insert(element.nodes.end(), added.begin(), added.end());
    element.type = "C3D27";
  }
}

void convert_layer_to_c3d21(Mesh& mesh, const std::string& surface) {
  const std::map<int, int> layer = layer_faces(mesh, surface);
  std::map<CornerKey, int> centre;  // a face between two layers gets one node
  for (const auto& [e, face] : layer) {
    reorient_to_bottom(mesh, e, face);
    MeshElement& element = mesh.elements[e];
    const CornerKey key = corner_key(element, 0);
    auto found = centre.find(key);
    if (found == centre.end())
      found =
          centre
              .emplace(key, mesh.add_node(map_point("C3D20", coords_of(mesh, element), {0, 0, -1})))
              .first;
    element.nodes.push_back(found->second);
    element.type = "C3D21";
  }
  set_surface_to_bottom(mesh, surface, layer);
}

std::vector<int> convert_layer_to_c3d28(Mesh& mesh, const std::string& surface) {
  std::map<int, int> layer = layer_faces(mesh, surface);

  // Face adjacency of the C3D20 part by corner sets.
  std::map<CornerKey, std::vector<FaceRef>> by_corners;
  for (int e = 0; e < static_cast<int>(mesh.elements.size()); ++e)
    if (mesh.elements[e].type == "C3D20")
      for (int f = 0; f < 6; ++f) by_corners[corner_key(mesh.elements[e], f)].push_back({e, f});

  // Closure: walk the side faces of the layer.
  std::deque<int> queue;
  for (const auto& kv : layer) queue.push_back(kv.first);
  while (!queue.empty()) {
    const int e = queue.front();
    queue.pop_front();
    const int bottom = layer.at(e);
    const CornerKey bottom_key = corner_key(mesh.elements[e], bottom);
    for (int g = 0; g < 6; ++g) {
      if (face_axis(g).axis == face_axis(bottom).axis) continue;  // bottom or top
      const CornerKey side = corner_key(mesh.elements[e], g);
      const auto& sharing = by_corners[side];
      for (const FaceRef& other : sharing) {
        if (other.element == e) continue;
        // The bottom edge: the two corners common to the side face and the bottom face.
        std::vector<int> edge;
        std::set_intersection(side.begin(), side.end(), bottom_key.begin(), bottom_key.end(),
                              std::back_inserter(edge));
        const auto in_layer = layer.find(other.element);
        if (in_layer != layer.end()) {
          const CornerKey ob = corner_key(mesh.elements[other.element], in_layer->second);
          if (!std::includes(ob.begin(), ob.end(), edge.begin(), edge.end()))
            throw std::invalid_argument("convert_layer_to_c3d28: " + element_name(e) + " and " +
                                        element_name(other.element) +
                                        " share a side face with their contact faces not aligned");
          continue;
        }
        // Join the neighbour through its free face along the shared bottom edge.
        int join = -1;
        for (int h = 0; h < 6; ++h) {
          if (h == other.face) continue;
          const CornerKey hk = corner_key(mesh.elements[other.element], h);
          if (!std::includes(hk.begin(), hk.end(), edge.begin(), edge.end())) continue;
          if (by_corners[hk].size() == 1) join = h;
        }
        if (join < 0)
          throw std::invalid_argument(
              "convert_layer_to_c3d28: the C3D28 layer on surface " + to_upper(surface) +
              " cannot be closed: " + element_name(other.element) + " borders " + element_name(e) +
              " through a side face but has no free face along its bottom edge");
        layer.emplace(other.element, join);
        queue.push_back(other.element);
      }
    }
  }

  const std::vector<Vec3>& nat28 = natural_nodes("C3D28");
  std::map<std::pair<int, int>, int> edge_nodes;     // (nearest corner, other corner)
  std::map<std::array<int, 5>, int> interior_nodes;  // (sorted face corners, nearest corner)
  std::vector<int> converted;
  for (const auto& [e, face] : layer) {
    reorient_to_bottom(mesh, e, face);
    MeshElement& element = mesh.elements[e];
    const std::vector<Vec3> x = coords_of(mesh, element);
    std::vector<int> nodes(28);
    for (int i = 0; i < 8; ++i) nodes[i] = element.nodes[i];
    for (int i = 0; i < 4; ++i) nodes[8 + i] = element.nodes[16 + i];   // vertical mid-edges
    for (int i = 0; i < 4; ++i) nodes[12 + i] = element.nodes[12 + i];  // top mid-edges
    const CornerKey face_key = corner_key(element, 0);
    for (int k = 16; k < 28; ++k) {
      const Vec3& p = nat28[k];
      // Nearest bottom corner (nodes 0-3) and, for an edge node, the other end of its edge.
      int nearest = 0;
      double best = 1e9;
      for (int c = 0; c < 4; ++c) {
        const Vec3& q = nat28[c];
        const double d = std::abs(q[0] - p[0]) + std::abs(q[1] - p[1]);
        if (d < best) {
          best = d;
          nearest = c;
        }
      }
      const bool on_edge =
          std::abs(std::abs(p[0]) - 1) < 1e-12 || std::abs(std::abs(p[1]) - 1) < 1e-12;
      int* slot = nullptr;
      if (on_edge) {
        // The edge partner differs from `nearest` in the coordinate that is not +-1.
        const int free_axis = std::abs(std::abs(p[0]) - 1) < 1e-12 ? 1 : 0;
        int other = -1;
        for (int c = 0; c < 4; ++c)
          if (c != nearest && nat28[c][1 - free_axis] == nat28[nearest][1 - free_axis]) other = c;
        const auto key = std::make_pair(element.nodes[nearest], element.nodes[other]);
        auto it = edge_nodes.find(key);
        if (it == edge_nodes.end()) it = edge_nodes.emplace(key, -1).first;
        slot = &it->second;
      } else {
        const std::array<int, 5> key{face_key[0], face_key[1], face_key[2], face_key[3],
                                     element.nodes[nearest]};
        auto it = interior_nodes.find(key);
        if (it == interior_nodes.end()) it = interior_nodes.emplace(key, -1).first;
        slot = &it->second;
      }
      if (*slot < 0) *slot = mesh.add_node(map_point("C3D20", x, p));
      nodes[k] = *slot;
    }
    element.nodes = std::move(nodes);
    element.type = "C3D28";
    converted.push_back(e);
  }
  set_surface_to_bottom(mesh, surface, layer);
  mesh.remove_unused_nodes();
  return converted;
}

}  // namespace styk::mesher
