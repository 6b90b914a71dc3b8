#include "model_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>

#include "beam_warnings.hpp"
#include "shell_warnings.hpp"

namespace styk::solver_detail {
namespace {

constexpr double kLockingPoisson = 0.45;
// D_11 / E of an isotropic 3D or plane-strain material at nu = 0.45 is 3.8 (and grows without
// bound towards 0.5); plane stress stays below 1.3. Above this the element is bulk-dominated.
constexpr double kBulkDominated = 3.0;
constexpr double kDistortedRatio = 0.1;

// Poisson's ratio from which a formulation's displacement error passes 10 %, measured by
// `styk study stability` (sweep "poisson": the SPEC §3.1.7 cylinder on 4 x 6 elements,
// docs/stability.md; tests/verification/atlas_warnings_test.cpp asserts each bracket). Types not
// listed: kLockingPoisson if fully integrated (locks()), never otherwise.
struct LockingOnset {
  const char* type;
  double poisson;
};
constexpr LockingOnset kMeasuredOnsets[] = {
    {"C3D8", 0.45},      // passes at 0.4, fails at 0.45
    {"C3D8R", 0.495},    // the hourglass control's stiffness follows the bulk modulus
    {"C3D14", 0.495},    // passes at 0.49, fails at 0.499
    {"C3D20", 0.495},    // ditto
    {"C3D27", 0.495},    // ditto
    {"C3D21", 0.495},    // ditto
    {"C3D28", 0.49995},  // passes at 0.4999, fails at 0.49999 (its bicubic face)
    {"C3D20R", 1.0},     // never: passes at 0.49999
    {"C3D8I", 1.0},      // never: passes at 0.49999
};

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

bool is_cube_solid(const TElement& element) {
  const DofSet active = element.active_dofs();
  if (element.node_dofs() != 3 || !(active[0] && active[1] && active[2]) ||
      element.section_measure() != SectionMeasure::None)
    return false;
  for (const Vec3& xi : element.natural_nodes())
    for (double c : xi)
      if (std::abs(c) > 1.0 + 1e-12) return false;
  return true;
}

bool bulk_dominated(const TElement& element, const Material& material) {
  if (element.section_measure() == SectionMeasure::Area) return false;  // trusses
  if (element.section_measure() == SectionMeasure::Beam) return false;  // uniaxial fibres
  if (element.section_measure() == SectionMeasure::Shell) return false;  // plane stress
  const MaterialPoint point = material_point(material);
  if (!point.isotropic) return false;  // the bulk-dominance rule is stated for isotropic laws
  Matrix6d D;
  element.dee(point, D);
  return D.cwiseAbs().maxCoeff() > kBulkDominated * point.young;
}

// Whether `element` locks volumetrically by construction: fully integrated (more points in its
// full rule than in its reduced one), no incompatible modes.
bool locks(const TElement& element) {
  if (element.incompatible_mode_count() > 0) return false;
  return element.rule(RuleKind::Full).size() > element.rule(RuleKind::Reduced).size();
}

// The Poisson's ratio from which `element` locks (above 0.5: never).
double locking_onset(const TElement& element) {
  for (const LockingOnset& o : kMeasuredOnsets)
    if (element.name() == o.type) return o.poisson;
  return locks(element) ? kLockingPoisson : 1.0;
}

// min / max of the point measure (det J) over the element's full rule; 1 when it cannot be
// evaluated (an inverted element is reported by the assembly, at its integration point).
double measure_ratio(const Model& model, const TElement& element, const IntegrationRule& rule,
                     int e, double cross_section) {
  const int n = element.node_count();
  ElementGeometry g;
  g.X.resize(n, 3);
  g.id = model.elements[e].id;
  g.where = model.elements[e].where;
  g.cross_section = cross_section;
  const int* nodes = model.element_nodes(e);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) g.X(a, d) = model.coords[nodes[a]][d];
  if (rule.size() < 2) return 1.0;
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
  double lo = INFINITY, hi = 0.0;
  try {
    for (int k = 0; k < rule.size(); ++k) {
      element.der(rule.points[k], N, dN);
      const double measure = element.point_measure(g, dN, dNdx, k + 1);
      lo = std::min(lo, measure);
      hi = std::max(hi, measure);
    }
  } catch (const InputError&) {
    return 1.0;
  }
  return hi > 0.0 ? lo / hi : 1.0;
}

}  // namespace

int spurious_zero_energy_modes(const TElement& element) {
  if (!is_cube_solid(element)) return 0;
  // A 2 x 2 x 2 patch of the reference cube, nodes merged by position.
  const std::vector<Vec3>& xi = element.natural_nodes();
  const int n = element.node_count();
  std::map<std::array<long long, 3>, int> index;
  std::vector<std::vector<int>> patch_nodes;
  for (int cell = 0; cell < 8; ++cell) {
    std::vector<int> ids;
    for (const Vec3& p : xi) {
      std::array<long long, 3> key{};
      for (int d = 0; d < 3; ++d) key[d] = std::llround((p[d] + 2.0 * ((cell >> d) & 1)) * 1e6);
      const auto it = index.emplace(key, static_cast<int>(index.size())).first;
      ids.push_back(it->second);
    }
    patch_nodes.push_back(std::move(ids));
  }
  Material unit;
  unit.young = 1.0;
  unit.poisson = 0.3;
  const int dofs = 3 * static_cast<int>(index.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  ElementGeometry g;
  g.X.resize(n, 3);
  for (int cell = 0; cell < 8; ++cell) {
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) g.X(a, d) = xi[a][d] + 2.0 * ((cell >> d) & 1);
    Eigen::MatrixXd Ke;
    element.stiffness(g, unit, RuleKind::Full, Ke);
    const std::vector<int>& ids = patch_nodes[cell];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        K.block<3, 3>(3 * ids[a], 3 * ids[b]) += Ke.block<3, 3>(3 * a, 3 * b);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  int zero = 0;
  for (Eigen::Index k = 0; k < values.size(); ++k) zero += std::abs(values[k]) < 1e-9 * largest;
  return std::max(0, zero - 6);
}

std::vector<std::string> model_warnings(const Model& model, const PreparedModel& prepared) {
  std::vector<std::string> warnings;
  // Per type: zero-energy modes (computed once per type) and the element count.
  std::map<const TElement*, int> count_of_type;
  for (const TElement* f : prepared.formulation) ++count_of_type[f];
  for (const auto& [f, count] : count_of_type) {
    const int modes = spurious_zero_energy_modes(*f);
    if (modes > 0)
      warnings.push_back(std::to_string(count) + " elements of type " + f->name() + " have " +
                         std::to_string(modes) +
                         " zero-energy (hourglass) modes in a 2 x 2 x 2 patch beyond the rigid "
                         "motions: their displacements and stresses can be garbage; use a type "
                         "with hourglass control (C3D8R) or full integration (C3D8I, C3D20)");
  }

  // Locking, per section and type.
  std::map<std::pair<int, const TElement*>, std::pair<int, const Material*>> locking;
  for (int e = 0; e < model.element_count(); ++e) {
    const int s = model.elements[e].section;
    const Material* material = prepared.material[e];
    if (s < 0 || material == nullptr || !material->poisson || !material->young) continue;
    const TElement& f = *prepared.formulation[e];
    if (*material->poisson < locking_onset(f)) continue;
    // Mean dilatation cures locking of a rule with more than one point; a one-point rule has
    // nothing to average (C3D8R's locking comes from its hourglass control).
    if (model.sections[s].selective_volumetric && f.rule(RuleKind::Full).size() > 1) continue;
    if (!bulk_dominated(f, *material)) continue;
    auto& entry = locking[{s, prepared.formulation[e]}];
    ++entry.first;
    entry.second = material;
  }
  for (const auto& [key, entry] : locking) {
    const Section& section = model.sections[key.first];
    const int count = entry.first;
    const Material& material = *entry.second;
    const TElement& f = *key.second;
    const std::string cure = f.rule(RuleKind::Full).size() > 1
                                 ? "add TECHNIQUE=SELECTIVE to the *SOLID SECTION"
                                 : "use C3D8I or C3D20R (TECHNIQUE=SELECTIVE cannot help a "
                                   "one-point rule)";
    warnings.push_back(section.where.file + ":" + std::to_string(section.where.line) + ": " +
                       std::to_string(count) + " " + f.name() + " elements of element set " +
                       section.elset + " lock volumetrically: " + "material " + material.name +
                       " has Poisson's ratio " + format("%g", *material.poisson) + " (" + f.name() +
                       " locks from " + format("%g", locking_onset(f)) + "); " + cure);
  }

  // Beams: shear locking of fully integrated slender beams, spurious modes (beam_warnings.hpp).
  for (std::string& warning : beam_warnings(model, prepared))
    warnings.push_back(std::move(warning));
  // Shells: shear locking of thin S8, spurious modes of 2x2 rules (shell_warnings.hpp).
  for (std::string& warning : shell_warnings(model, prepared))
    warnings.push_back(std::move(warning));

  // Distortion: the worst element and how many are beyond the ratio.
  std::map<const TElement*, IntegrationRule> rules;
  int distorted = 0, worst = -1;
  double worst_ratio = 1.0;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& f = *prepared.formulation[e];
    if (f.section_measure() == SectionMeasure::Area) continue;  // a truss has no shape to lose
    auto rule = rules.find(&f);  // one rule per type, not one per element
    if (rule == rules.end()) rule = rules.emplace(&f, f.rule(RuleKind::Full)).first;
    const double ratio = measure_ratio(model, f, rule->second, e, cross_section_of(model, e));
    if (ratio >= kDistortedRatio) continue;
    ++distorted;
    if (ratio < worst_ratio) worst_ratio = ratio, worst = e;
  }
  if (distorted > 0) {
    const Element& w = model.elements[worst];
    warnings.push_back(
        std::to_string(distorted) + (distorted == 1 ? " element is" : " elements are") +
        " strongly distorted (det J varies more than 10 times inside the element); worst: "
        "element " +
        std::to_string(w.id) + " (" + w.type + ", line " + std::to_string(w.where.line) +
        "), min/max det J " + format("%.3g", worst_ratio) +
        ": accuracy drops there (constant stress is still exact); reshape or refine");
  }
  return warnings;
}

}  // namespace styk::solver_detail
