#include "styk/render/skin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Core>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

using Key = std::array<int, 4>;  // sorted corner node indices; a triangle pads with -1 first

// Corner local indices of each face of one formulation, computed once per formulation.
struct FaceCorners {
  std::vector<std::array<int, 4>> corners;  // -1 in slot 3 for a triangle
};

bool inside_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Barycentric test in the plane of the triangle (natural coordinates are exact small numbers).
  using V = Eigen::Map<const Eigen::Vector3d>;
  const Eigen::Vector3d v0 = V(c.data()) - V(a.data()), v1 = V(b.data()) - V(a.data()),
                        v2 = V(p.data()) - V(a.data());
  const double d00 = v0.dot(v0), d01 = v0.dot(v1), d02 = v0.dot(v2), d11 = v1.dot(v1),
               d12 = v1.dot(v2);
  const double denom = d00 * d11 - d01 * d01;
  if (std::abs(denom) < 1e-14) return false;
  const double u = (d11 * d02 - d01 * d12) / denom, v = (d00 * d12 - d01 * d02) / denom;
  const double eps = 1e-9;
  // Also require p to lie in the plane: the residual of the projection.
  const Eigen::Vector3d r = u * v0 + v * v1 - v2;
  return u >= -eps && v >= -eps && u + v <= 1.0 + eps && r.squaredNorm() < 1e-18;
}

FaceCorners face_corners(const TElement& element) {
  FaceCorners out;
  for (const FaceDef& face : drawn_faces(element)) {
    std::array<int, 4> c{-1, -1, -1, -1};
    const int n = face_corner_count(element, face);
    for (int i = 0; i < n; ++i) c[i] = face.nodes[i];
    out.corners.push_back(c);
  }
  return out;
}

Key face_key(const int* nodes, const std::array<int, 4>& corners) {
  Key key{-1, nodes[corners[0]], nodes[corners[1]], nodes[corners[2]]};
  if (corners[3] >= 0) key[0] = nodes[corners[3]];
  // Sorting network for 4 values.
  const auto order = [&key](int i, int j) {
    if (key[i] > key[j]) std::swap(key[i], key[j]);
  };
  order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
  return key;
}

int smallest_corner(const Key& key) { return key[0] >= 0 ? key[0] : key[1]; }

}  // namespace

int face_corner_count(const TElement& element, const FaceDef& face) {
  if (face.nodes.size() < 4) return static_cast<int>(face.nodes.size());
  const std::vector<Vec3>& xi = element.natural_nodes();
  return inside_triangle(xi[face.nodes[3]], xi[face.nodes[0]], xi[face.nodes[1]], xi[face.nodes[2]])
             ? 3
             : 4;
}

bool is_planar_element(const TElement& element) {
  const ElementForm form = element.form();
  return form == ElementForm::Planar || form == ElementForm::Axisymmetric;
}

std::vector<FaceDef> drawn_faces(const TElement& element) {
  if (!is_planar_element(element)) return element.faces();
  FaceDef area;  // the element's own nodes, corners first as the formulation lists them
  for (int k = 0; k < element.node_count(); ++k) area.nodes.push_back(k);
  std::vector<FaceDef> faces(element.faces().size());  // the edges: never drawn
  faces.push_back(area);
  return faces;
}

bool is_line_element(const TElement& element) { return element.form() == ElementForm::Line; }

std::vector<int> line_node_order(const TElement& element) {
  const std::vector<Vec3>& xi = element.natural_nodes();
  std::vector<int> order(xi.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&xi](int a, int b) { return xi[a][0] < xi[b][0]; });
  return order;
}

std::vector<const TElement*> element_formulations(const Model& model,
                                                  const ElementRegistry& registry) {
  std::vector<const TElement*> out(model.elements.size(), nullptr);
  const std::string* last_type = nullptr;
  const TElement* last = nullptr;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& element = model.elements[e];
    if (!last_type || *last_type != element.type) {
      last = registry.find(element.type);
      last_type = &element.type;
      if (!last) {
        std::string known;
        for (const std::string& name : registry.names())
          known += (known.empty() ? "" : ", ") + name;
        throw InputError(element.where, "element " + std::to_string(element.id) + " has type " +
                                            element.type + ", which no loaded formulation draws " +
                                            "(known: " + known + ")");
      }
      if (last->node_count() != element.node_count)
        throw InputError(element.where,
                         "element " + std::to_string(element.id) + " (" + element.type + ") has " +
                             std::to_string(element.node_count) + " nodes, " +
                             "the formulation has " + std::to_string(last->node_count()));
    }
    out[e] = last;
  }
  return out;
}

std::vector<SkinFace> extract_skin(const Model& model,
                                   const std::vector<const TElement*>& formulations,
                                   const std::vector<int>& elements) {
  // Corner tables per distinct formulation (a handful), looked up by pointer.
  std::map<const TElement*, FaceCorners> tables;
  std::vector<const FaceCorners*> corners_of(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const TElement* f = formulations[elements[i]];
    auto it = tables.find(f);
    if (it == tables.end()) it = tables.emplace(f, face_corners(*f)).first;
    corners_of[i] = &it->second;
  }

  // Pass 1: bucket sizes by smallest corner node.
  const std::size_t node_count = model.coords.size();
  std::vector<std::uint32_t> offset(node_count + 1, 0);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const int* nodes = model.element_nodes(elements[i]);
    for (const auto& c : corners_of[i]->corners)
      if (c[0] >= 0) ++offset[smallest_corner(face_key(nodes, c)) + 1];
  }
  for (std::size_t n = 0; n < node_count; ++n) offset[n + 1] += offset[n];

  // Pass 2: fill the buckets with (position in `elements`, face).
  struct Entry {
    std::uint32_t element_slot;
    std::uint32_t face;
  };
  std::vector<Entry> entries(offset[node_count]);
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const int* nodes = model.element_nodes(elements[i]);
    const auto& corners = corners_of[i]->corners;
    for (std::size_t f = 0; f < corners.size(); ++f)
      if (corners[f][0] >= 0)  // a planar element's edges are not drawn (drawn_faces)
        entries[fill[smallest_corner(face_key(nodes, corners[f]))]++] =
            Entry{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(f)};
  }

  // Pass 3: within each bucket, sort by key; keys that occur once are skin.
  std::vector<SkinFace> skin;
  std::vector<std::pair<Key, Entry>> bucket;
  for (std::size_t n = 0; n < node_count; ++n) {
    const std::uint32_t begin = offset[n], end = offset[n + 1];
    if (begin == end) continue;
    bucket.clear();
    for (std::uint32_t k = begin; k < end; ++k) {
      const Entry& entry = entries[k];
      const int* nodes = model.element_nodes(elements[entry.element_slot]);
      bucket.emplace_back(face_key(nodes, corners_of[entry.element_slot]->corners[entry.face]),
                          entry);
    }
    std::sort(bucket.begin(), bucket.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first : a.second.element_slot < b.second.element_slot;
    });
    for (std::size_t k = 0; k < bucket.size();) {
      std::size_t run = k + 1;
      while (run < bucket.size() && bucket[run].first == bucket[k].first) ++run;
      if (run - k == 1)
        skin.push_back(SkinFace{elements[bucket[k].second.element_slot],
                                static_cast<int>(bucket[k].second.face)});
      k = run;
    }
  }
  return skin;
}

}  // namespace styk::render
