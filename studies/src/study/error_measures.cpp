#include "styk/studies/study/error_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "element_geometry.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::studies {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double model_size(const Model& model) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& x : model.coords)
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

int node_at(const Model& model, const Vec3& at, const std::string& label) {
  int best = -1;
  double best_d = INFINITY;
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    const double d = std::hypot(x[0] - at[0], x[1] - at[1], x[2] - at[2]);
    if (d < best_d) best_d = d, best = n;
  }
  if (best < 0 || best_d > 1e-6 * model_size(model))
    throw InputError({model.source, 0}, "no node at the named point of '" + label + "' (" +
                                            std::to_string(at[0]) + ", " + std::to_string(at[1]) +
                                            ", " + std::to_string(at[2]) + ")");
  return best;
}

// The section of an element holding node n (the region of the exact solution there).
int region_of_node(const Model& model, int n) {
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    for (int a = 0; a < model.elements[e].node_count; ++a)
      if (nodes[a] == n) return model.elements[e].section;
  }
  return 0;
}

double relative(double computed, double exact) {
  return std::abs(computed - exact) / std::max(std::abs(exact), 1e-300);
}

double contract(const Vec3& a, const Tensor6& s, const Vec3& b) {
  const double m[3][3] = {{s[0], s[3], s[4]}, {s[3], s[1], s[5]}, {s[4], s[5], s[2]}};
  double v = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v += a[i] * m[i][j] * b[j];
  return v;
}

// The incompatible-mode amplitudes a = -Kaa^-1 Kau^T u of an element (C3D8I) from its nodal
// displacements, over its own rule as the solver condensed them; empty for other elements.
Eigen::VectorXd incompatible_modes(const TElement& element, const ElementGeometry& g,
                                   const Matrix6d& D, const Eigen::VectorXd& u) {
  const int m = element.incompatible_mode_count(), n = element.node_count();
  if (m == 0) return {};
  const IntegrationRule rule = element.rule(RuleKind::Full);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3), B(6, 3 * n), G(6, m);
  Eigen::MatrixXd Kaa = Eigen::MatrixXd::Zero(m, m), Kau = Eigen::MatrixXd::Zero(m, 3 * n);
  for (int q = 0; q < rule.size(); ++q) {
    element.der(rule.points[q], N, dN);
    const double detJ = element.point_measure(g, N, dN, dNdx, q + 1);
    element.bee(dNdx, B);
    element.incompatible_bee(g, rule.points[q], detJ, G);
    const double w = rule.weights[q] * detJ;
    Kaa.noalias() += w * G.transpose() * D * G;
    Kau.noalias() += w * G.transpose() * D * B;
  }
  return -Kaa.ldlt().solve(Kau * u);
}

IntegrationRule error_rule(const TElement& element) {
  return detail::is_hexahedron(element) ? gauss_rule(4, 4, 4) : element.rule(RuleKind::Full);
}

double point_displacement_error(const Model& model, const IncrementResult& r,
                                const ExactSolution& exact, const PointProbe& p) {
  const int n = node_at(model, p.at, p.label);
  if (exact.scalar()) return relative(r.scalar.value.at(n), exact.temperature(model.coords[n]));
  const Vec3 u = exact.displacement(model.coords[n], region_of_node(model, n));
  return relative(dot(r.U.at(n), p.direction), dot(u, p.direction));
}

double point_stress_error(const Model& model, const IncrementResult& r, const ExactSolution& exact,
                          const StressProbe& p) {
  const int n = node_at(model, p.at, p.label);
  if (exact.scalar()) {
    const Vec3 g = exact.gradient(model.coords[n]);
    const double k = exact.conductivity();
    const Vec3 q{-k * g[0], -k * g[1], -k * g[2]};
    return relative(dot(r.scalar.flux_nodal.at(n), p.a), dot(q, p.a));
  }
  if (r.S_nodal_I.empty())
    throw InputError({model.source, 0}, "the solve recovered no nodal stresses");
  const Tensor6 s = exact.stress(model.coords[n], region_of_node(model, n));
  return relative(contract(p.a, r.S_nodal_I.at(n), p.b), contract(p.a, s, p.b));
}

double contact_pressure_error(const IncrementResult& r, double exact) {
  double worst = 0;
  for (const ContactNodeResult& c : r.contact) worst = std::max(worst, relative(c.pressure, exact));
  return r.contact.empty() ? std::numeric_limits<double>::quiet_NaN() : worst;
}

}  // namespace

double relative_l2_error(const Model& model, const IncrementResult& r,
                         const ElementRegistry& registry, const ExactSolution& exact) {
  double error2 = 0, norm2 = 0;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& element = detail::formulation_of(model, registry, e);
    const ElementGeometry g = detail::geometry_of(model, e);
    const IntegrationRule rule = error_rule(element);
    const int n = element.node_count(), region = model.elements[e].section;
    const int* nodes = model.element_nodes(e);
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
    for (int q = 0; q < rule.size(); ++q) {
      element.der(rule.points[q], N, dN);
      const double w = rule.weights[q] * element.point_measure(g, N, dN, dNdx, q + 1);
      const Vec3 x = detail::map_point(N, g);
      if (exact.scalar()) {
        double t = 0;
        for (int a = 0; a < n; ++a) t += N(a) * r.scalar.value[nodes[a]];
        const double te = exact.temperature(x);
        error2 += w * (t - te) * (t - te);
        norm2 += w * te * te;
        continue;
      }
      Vec3 u{0, 0, 0};
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) u[d] += N(a) * r.U[nodes[a]][d];
      const Vec3 ue = exact.displacement(x, region);
      for (int d = 0; d < 3; ++d) {
        error2 += w * (u[d] - ue[d]) * (u[d] - ue[d]);
        norm2 += w * ue[d] * ue[d];
      }
    }
  }
  return std::sqrt(error2 / norm2);
}

double relative_energy_error(const Model& model, const IncrementResult& r,
                             const ElementRegistry& registry, const ExactSolution& exact) {
  // The energy norm of the error of the element's strain field (B u_h, plus the incompatible
  // modes G a where the element has them), integrated with the same rule as the L2 error:
  // independent of the element's own quadrature, so a reduced rule that samples the stress only
  // at its superconvergent points does not flatter its family.
  double error2 = 0, norm2 = 0;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& element = detail::formulation_of(model, registry, e);
    const ElementGeometry g = detail::geometry_of(model, e);
    const IntegrationRule rule = error_rule(element);
    const int n = element.node_count(), region = model.elements[e].section;
    const int* nodes = model.element_nodes(e);
    Eigen::VectorXd N(n), u(3 * n), modes;
    Eigen::MatrixXd dN(n, 3), dNdx(n, 3), B(6, 3 * n), G(6, element.incompatible_mode_count());
    Matrix6d D = Matrix6d::Zero();
    if (!exact.scalar()) {
      const Section& section = model.sections.at(region);
      element.dee(material_point(model.materials.at(section.material_index)), D);
      for (int a = 0; a < n; ++a)
        for (int d = 0; d < 3; ++d) u(3 * a + d) = r.U[nodes[a]][d];
      modes = incompatible_modes(element, g, D, u);
    }
    for (int q = 0; q < rule.size(); ++q) {
      element.der(rule.points[q], N, dN);
      const double detJ = element.point_measure(g, N, dN, dNdx, q + 1);
      const double w = rule.weights[q] * detJ;
      const Vec3 x = detail::map_point(N, g);
      if (exact.scalar()) {
        Eigen::Vector3d gh = Eigen::Vector3d::Zero();
        for (int a = 0; a < n; ++a) gh += r.scalar.value[nodes[a]] * dNdx.row(a).transpose();
        const Vec3 ge = exact.gradient(x);
        const double k = exact.conductivity();
        for (int d = 0; d < 3; ++d) {
          error2 += w * k * (gh[d] - ge[d]) * (gh[d] - ge[d]);
          norm2 += w * k * ge[d] * ge[d];
        }
        continue;
      }
      element.bee(dNdx, B);
      Eigen::Matrix<double, 6, 1> strain_h = B * u;
      if (modes.size() > 0) {
        element.incompatible_bee(g, rule.points[q], detJ, G);
        strain_h.noalias() += G * modes;
      }
      const Tensor6 se = exact.stress(x, region);
      const double E = exact.young(region), nu = exact.poisson(region);
      const double shear = E / (2 * (1 + nu));
      Eigen::Matrix<double, 6, 1> strain;  // engineering shear, as B
      strain << (se[0] - nu * (se[1] + se[2])) / E, (se[1] - nu * (se[0] + se[2])) / E,
          (se[2] - nu * (se[0] + se[1])) / E, se[3] / shear, se[4] / shear, se[5] / shear;
      const Eigen::Matrix<double, 6, 1> diff = strain_h - strain;
      error2 += w * diff.dot(D * diff);
      norm2 += w * strain.dot(D * strain);
    }
  }
  return std::sqrt(error2 / norm2);
}

ErrorArray measure_errors(const Model& model, const IncrementResult& result,
                          const ElementRegistry& registry, const ExactSolution& exact,
                          const ProblemProbes& probes) {
  ErrorArray out{};
  out[static_cast<int>(Measure::PointDisplacement)] =
      point_displacement_error(model, result, exact, probes.displacement);
  out[static_cast<int>(Measure::PointStress)] =
      point_stress_error(model, result, exact, probes.stress);
  out[static_cast<int>(Measure::DisplacementL2)] =
      relative_l2_error(model, result, registry, exact);
  out[static_cast<int>(Measure::Energy)] = relative_energy_error(model, result, registry, exact);
  if (probes.contact_pressure) {
    const double e = contact_pressure_error(result, *probes.contact_pressure);
    if (std::isfinite(e)) out[static_cast<int>(Measure::ContactPressure)] = e;
  }
  return out;
}

}  // namespace styk::studies
