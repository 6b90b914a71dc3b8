// The beam element types: names, node layout, shape functions, stations and output points. The
// mechanics (stiffness, loads, section forces, fibre stresses) is in beam_mechanics.cpp.
#include "styk/elements/beam.hpp"

#include <algorithm>
#include <cmath>

#include "beam_station.hpp"

namespace styk {
namespace {

struct TypeInfo {
  const char* name;
  int nodes;
  bool planar;
  bool reduced_only;
};

TypeInfo info(BeamType type) {
  switch (type) {
    case BeamType::B21:
      return {"B21", 2, true, false};
    case BeamType::B22:
      return {"B22", 3, true, false};
    case BeamType::B31:
      return {"B31", 2, false, false};
    case BeamType::B31R:
      return {"B31R", 2, false, true};
    case BeamType::B32:
      return {"B32", 3, false, false};
    case BeamType::B32R:
      return {"B32R", 3, false, true};
  }
  return {"?", 2, false, false};
}

}  // namespace

Beam::Beam(BeamType type)
    : type_(type), planar_(info(type).planar), reduced_only_(info(type).reduced_only) {
  if (info(type).nodes == 2)
    nodes_ = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  else
    nodes_ = {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};  // node 2 in the middle
}

std::string Beam::name() const { return info(type_).name; }

std::string Beam::description() const {
  const bool linear = node_count() == 2;
  std::string text = std::string(linear ? "2-node linear" : "3-node quadratic") +
                     " Timoshenko beam " + (planar_ ? "in the x-y plane (ux, uy, rz)" : "in space");
  if (reduced_only_)
    return text + ", reduced integration (" + (linear ? "1 point" : "2 points") +
           ", the CalculiX name)";
  return text + ", reduced integration (" + (linear ? "1 point" : "2 points") +
         "; INTEGRATION=FULL: " + (linear ? "2" : "3") + ")";
}

DofSet Beam::active_dofs() const {
  if (planar_) return {true, true, false, false, false, true};
  return {true, true, true, true, true, true};
}

void Beam::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
               Eigen::Ref<Eigen::MatrixXd> dN) const {
  const double x = xi[0];
  dN.setZero();
  if (node_count() == 2) {
    N << 0.5 * (1.0 - x), 0.5 * (1.0 + x);
    dN(0, 0) = -0.5;
    dN(1, 0) = 0.5;
    return;
  }
  N << 0.5 * x * (x - 1.0), 1.0 - x * x, 0.5 * x * (x + 1.0);
  dN(0, 0) = x - 0.5;
  dN(1, 0) = -2.0 * x;
  dN(2, 0) = x + 0.5;
}

void Beam::stations(RuleKind kind, std::vector<double>& xi, std::vector<double>& weights) const {
  const bool full = kind == RuleKind::Full && !reduced_only_;
  gauss_legendre(full ? node_count() : node_count() - 1, xi, weights);
}

int Beam::section_stations(RuleKind kind) const {
  std::vector<double> xi, w;
  stations(kind, xi, w);
  return static_cast<int>(xi.size());
}

IntegrationRule Beam::rule(RuleKind kind) const {
  std::vector<double> xi, w;
  stations(kind, xi, w);
  IntegrationRule rule;
  rule.label = std::to_string(xi.size()) + "-point Gauss along the axis x 4 fibre points";
  for (std::size_t k = 0; k < xi.size(); ++k)
    for (int fibre = 0; fibre < 4; ++fibre) {
      rule.points.push_back({xi[k], 0.0, 0.0});
      rule.weights.push_back(w[k] / 4.0);
    }
  return rule;
}

double Beam::point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& /*N*/,
                           const Eigen::Ref<const Eigen::MatrixXd>& dN,
                           Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const {
  const Eigen::Vector3d tangent = g.X.transpose() * dN.col(0);
  const double J = tangent.norm();
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  if (!(J > 1e-12 * scale))
    throw InputError(g.where, beam_detail::label(*this, g) + ": zero length at point " +
                                  std::to_string(point) + " (its nodes coincide)");
  const Eigen::Vector3d t = tangent / J;
  for (Eigen::Index a = 0; a < dN.rows(); ++a) dNdx.row(a) = (dN(a, 0) / J) * t.transpose();
  const double area =
      g.section != nullptr && g.section->beam && check_beam_section(*g.section->beam).empty()
          ? beam_section_properties(*g.section->beam).area
          : g.cross_section;
  return J * area;
}

}  // namespace styk
