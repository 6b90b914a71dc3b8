#include "styk/mesher/quality.hpp"

#include <array>
#include <map>
#include <set>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace styk::mesher {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The corner nodes of every face of a type, going round the face (from its own faces(): any
// shape, plug-ins included), and the corner edges they bound.
struct CornerTopology {
  std::vector<std::vector<int>> faces;
  std::vector<std::array<int, 2>> edges;
};

CornerTopology corner_topology(const TElement& element) {
  CornerTopology out;
  const std::vector<int> corners = corner_nodes(element);
  std::set<std::array<int, 2>> edges;
  for (const FaceDef& face : element.faces()) {
    std::vector<int> c;
    for (int k : face.nodes)
      if (std::binary_search(corners.begin(), corners.end(), k)) c.push_back(k);
    for (std::size_t i = 0; i < c.size() && c.size() > 1; ++i)
      edges.insert({std::min(c[i], c[(i + 1) % c.size()]), std::max(c[i], c[(i + 1) % c.size()])});
    out.faces.push_back(std::move(c));
  }
  out.edges.assign(edges.begin(), edges.end());
  return out;
}

Eigen::Vector3d row(const Eigen::MatrixXd& X, int i) { return X.row(i).transpose(); }

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = a.dot(b) / (a.norm() * b.norm());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

}  // namespace

QualityReport assess_quality(const Model& model, const ElementRegistry& registry) {
  QualityReport report;
  report.min_jacobian_ratio = 1.0;
  std::map<const TElement*, CornerTopology> topology;
  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    const TElement* formulation = registry.find(element.type);
    if (!formulation)
      throw InputError(element.where, "element " + std::to_string(element.id) + ": type " +
                                          element.type + " is not registered");
    const int n = formulation->node_count();
    ElementGeometry g;
    g.X.resize(n, 3);
    g.id = element.id;
    g.where = element.where;
    const int* nodes = model.element_nodes(e);
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) g.X(i, d) = model.coords[nodes[i]][d];

    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
    double lo = 1e300, hi = 0.0;
    const IntegrationRule rule = formulation->rule(RuleKind::Full);
    for (int p = 0; p < rule.size(); ++p) {
      formulation->der(rule.points[p], N, dN);
      const double det = formulation->jacobian(g, dN, dNdx, p + 1);
      report.volume += det * rule.weights[p];
      lo = std::min(lo, det);
      hi = std::max(hi, det);
    }
    // At the nodes det J may legitimately be <= 0 on a valid element (the MacNeal-Harder patch
    // of SPEC §3.1.8 has such corners); it shows in the ratio but is not an error.
    const std::vector<Vec3>& natural = formulation->natural_nodes();
    for (int i = 0; i < n; ++i) {
      formulation->der(natural[i], N, dN);
      const double det = (dN.transpose() * g.X).determinant();
      lo = std::min(lo, det);
      hi = std::max(hi, det);
    }
    ElementQuality q;
    q.element = e;
    q.jacobian_ratio = lo / hi;
    auto known = topology.find(formulation);
    if (known == topology.end())
      known = topology.emplace(formulation, corner_topology(*formulation)).first;
    const CornerTopology& corners = known->second;
    double shortest = 1e300, longest = 0.0;
    for (const auto& edge : corners.edges) {
      const double length = (row(g.X, edge[0]) - row(g.X, edge[1])).norm();
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
    q.aspect_ratio = longest / shortest;
    for (const std::vector<int>& f : corners.faces) {
      if (f.size() != 4) continue;  // a triangle cannot warp
      const Eigen::Vector3d a = row(g.X, f[0]), b = row(g.X, f[1]), c = row(g.X, f[2]),
                            d = row(g.X, f[3]);
      const double w1 = angle_between((b - a).cross(c - a), (c - a).cross(d - a));
      const double w2 = angle_between((c - b).cross(d - b), (d - b).cross(a - b));
      q.warping_deg = std::max({q.warping_deg, w1, w2});
    }
    report.min_jacobian_ratio = std::min(report.min_jacobian_ratio, q.jacobian_ratio);
    report.max_jacobian_ratio = std::max(report.max_jacobian_ratio, q.jacobian_ratio);
    report.max_aspect_ratio = std::max(report.max_aspect_ratio, q.aspect_ratio);
    report.max_warping_deg = std::max(report.max_warping_deg, q.warping_deg);
    report.elements.push_back(q);
  }
  return report;
}

}  // namespace styk::mesher
