// Private: how one face of one formulation is drawn. The face is parametrised over (s, t) in
// [0, 1]^2 by the bilinear map of its corners' natural coordinates (a triangle is the quad with
// its last corner repeated) and evaluated with the element's own shape functions (DER), so curved
// faces of any formulation, plug-ins included, are drawn without knowing their node layout.
#pragma once

#include <array>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "styk/core/element.hpp"

namespace styk::render {

// Shape-function values and tangential derivatives on an (n+1) x (n+1) grid of (s, t), s fastest,
// restricted to the element nodes that are non-zero on the face.
struct FacePatch {
  int segments = 1;
  std::vector<int> nodes;  // element-local node indices
  std::vector<double> N;   // [point * nodes.size() + a]
  std::vector<double> dNds;
  std::vector<double> dNdt;
  int points() const { return (segments + 1) * (segments + 1); }
};

struct FaceShape {
  int corner_count = 4;
  std::array<int, 4> corners{};  // element-local; corners[3] == corners[2] for a triangle
  // Subdivisions per direction of a face whose geometry or field is not bilinear: 1 when the face
  // has only corner nodes, otherwise 2 x its polynomial degree (the most nodes on one edge minus
  // one, at least 2 when the face has interior nodes): quadratic faces 4, cubic 6.
  int curved_segments = 1;
  // Non-corner face nodes and their (s, t), for the test "is this face bilinear as placed".
  std::vector<int> extra_nodes;
  std::vector<std::array<double, 2>> extra_st;
  FacePatch flat;    // segments = 1
  FacePatch curved;  // segments = curved_segments (refinement level 0)
  // At least 2 segments per direction (= curved when that has 2 or more): a discrete field gives
  // each grid cell the value of the face node nearest to it in (s, t), so every face node needs
  // cells of its own.
  FacePatch split;
};

// The finest refinement level of a field's tessellation: curved_segments x 2^level per direction.
constexpr int kMaxRefinement = 3;

// Face shapes of the formulations of one model, built eagerly for every face of every formulation
// passed in (a handful). Finer grids for fields that curve more than the base grid follows
// (refined()) are made on first use and kept.
class FaceShapes {
 public:
  explicit FaceShapes(const std::vector<const TElement*>& formulations);
  const FaceShape& get(const TElement* element, int face) const {
    return shapes_.at(element)[static_cast<std::size_t>(face)];
  }
  // The grid of curved_segments x 2^level (level 1..kMaxRefinement) of a higher-order face.
  const FacePatch& refined(const TElement* element, int face, int level) const;

 private:
  std::map<const TElement*, std::vector<FaceShape>> shapes_;
  mutable std::map<std::tuple<const TElement*, int, int>, FacePatch> refined_;
};

}  // namespace styk::render
