// TElement's self-description defaults (element_description.hpp): the form inferred from the
// layout, the corner nodes and the linear VTK cell they make.
#include <algorithm>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk {
namespace {

Eigen::Vector3d point(const Vec3& x) { return {x[0], x[1], x[2]}; }

// Whether natural point p lies strictly inside the segment a-b (to 1e-9).
bool strictly_between(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Eigen::Vector3d ab = point(b) - point(a), ap = point(p) - point(a);
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0.0)) return false;
  const double t = ap.dot(ab) / length2;
  return t > 1e-9 && t < 1.0 - 1e-9 && (ap - t * ab).norm() < 1e-9;
}

}  // namespace

const char* form_name(ElementForm form) {
  switch (form) {
    case ElementForm::Solid:
      return "solid";
    case ElementForm::Planar:
      return "planar";
    case ElementForm::Axisymmetric:
      return "axisymmetric";
    case ElementForm::Line:
      return "line";
    case ElementForm::Shell:
      return "shell";
  }
  return "";
}

VtkCell vtk_first_nodes(int type, int count) {
  VtkCell cell{type, std::vector<int>(static_cast<std::size_t>(count))};
  for (int k = 0; k < count; ++k) cell.nodes[static_cast<std::size_t>(k)] = k;
  return cell;
}

std::vector<int> corner_nodes(const TElement& element) {
  const std::vector<Vec3>& xi = element.natural_nodes();
  const int n = static_cast<int>(xi.size());
  std::vector<int> corners;
  for (int k = 0; k < n; ++k) {
    bool between = false;
    for (int i = 0; i < n && !between; ++i)
      for (int j = i + 1; j < n && !between; ++j)
        between = i != k && j != k && strictly_between(xi[k], xi[i], xi[j]);
    if (!between) corners.push_back(k);
  }
  return corners;
}

Vec3 natural_centroid(const TElement& element) {
  const std::vector<int> corners = corner_nodes(element);
  Vec3 c{0.0, 0.0, 0.0};
  for (int k : corners)
    for (int d = 0; d < 3; ++d) c[d] += element.natural_nodes()[k][d] / corners.size();
  return c;
}

ElementForm TElement::form() const {
  if (faces().empty()) return ElementForm::Line;
  const std::vector<Vec3>& xi = natural_nodes();
  const bool flat = std::all_of(xi.begin(), xi.end(), [](const Vec3& p) { return p[2] == 0.0; });
  const bool edges = std::all_of(faces().begin(), faces().end(),
                                 [](const FaceDef& f) { return f.nodes.size() <= 3; });
  return flat && edges ? ElementForm::Planar : ElementForm::Solid;
}

VtkCell TElement::vtk_cell() const {
  const std::vector<int> c = corner_nodes(*this);
  const std::size_t count = c.size();
  switch (form()) {
    case ElementForm::Solid:
      if (count == 8) return {vtk::kHexahedron, c};
      if (count == 4) return {vtk::kTetra, c};
      // VTK's base triangle turns the other way round (its normal points away from the top).
      if (count == 6) return {vtk::kWedge, {c[0], c[2], c[1], c[3], c[5], c[4]}};
      break;
    case ElementForm::Planar:
    case ElementForm::Axisymmetric:
      if (count == 4) return {vtk::kQuad, c};
      if (count == 3) return {vtk::kTriangle, c};
      break;
    case ElementForm::Line:
      if (count == 2) return {vtk::kLine, c};
      break;
    case ElementForm::Shell:  // its reference surface
      if (count == 4) return {vtk::kQuad, c};
      if (count == 3) return {vtk::kTriangle, c};
      break;
  }
  return {};
}

}  // namespace styk
