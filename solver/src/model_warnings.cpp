#include "model_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <Eigen/LU>

#include "zero_energy_modes.hpp"

#include "beam_warnings.hpp"
#include "shell_warnings.hpp"
#include "warning_format.hpp"

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

// A linear tetrahedron (C3D4): a solid whose nodes are its 4 corners, integrated at one point.
// Its strain is constant: it is stiff in bending and, one volume constraint per element and about
// six elements per node, it locks volumetrically despite its single point.
bool linear_tetrahedron(const TElement& element) {
  return element.form() == ElementForm::Solid && element.node_count() == 4 &&
         corner_nodes(element).size() == 4 && element.rule(RuleKind::Full).size() == 1;
}

bool bulk_dominated(const TElement& element, const Material& material) {
  // Trusses and beams (uniaxial fibres), shells (plane stress in their lamina).
  if (element.form() == ElementForm::Line || element.form() == ElementForm::Shell) return false;
  const MaterialPoint point = material_point(material);
  if (!point.isotropic) return false;  // the bulk-dominance rule is stated for isotropic laws
  Matrix6d D;
  element.dee(point, D);
  return D.cwiseAbs().maxCoeff() > kBulkDominated * point.young;
}

// Whether `element` locks volumetrically by construction: fully integrated (more points in its
// full rule than in its reduced one) without incompatible modes, or a linear tetrahedron.
bool locks(const TElement& element) {
  if (element.incompatible_mode_count() > 0) return false;
  return element.rule(RuleKind::Full).size() > element.rule(RuleKind::Reduced).size() ||
         linear_tetrahedron(element);
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
      const double measure = element.point_measure(g, N, dN, dNdx, k + 1);
      lo = std::min(lo, measure);
      hi = std::max(hi, measure);
    }
  } catch (const InputError&) {
    return 1.0;
  }
  return hi > 0.0 ? lo / hi : 1.0;
}

// The smallest extent of the bounding box of a set of elements' nodes.
double thinnest_extent(const Model& model, const std::vector<int>& elements) {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int e : elements) {
    const int* nodes = model.element_nodes(e);
    for (int a = 0; a < model.elements[e].node_count; ++a)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], model.coords[nodes[a]][d]);
        hi[d] = std::max(hi[d], model.coords[nodes[a]][d]);
      }
  }
  return std::min({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

// The volume of a linear tetrahedron from its corners.
double tetrahedron_volume(const Model& model, int e) {
  const int* n = model.element_nodes(e);
  Eigen::Matrix3d edges;
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) edges(k, d) = model.coords[n[k + 1]][d] - model.coords[n[0]][d];
  return std::abs(edges.determinant()) / 6.0;
}

void hourglass_warnings(const PreparedModel& prepared, std::vector<std::string>& warnings) {
  // Per type: zero-energy modes (computed once per type) and the element count.
  std::map<const TElement*, int> count_of_type;
  for (const TElement* f : prepared.formulation) ++count_of_type[f];
  for (const auto& [f, count] : count_of_type) {
    const int modes = spurious_zero_energy_modes(*f);
    if (modes > 0)
      warnings.push_back(std::to_string(count) + " elements of type " + f->name() + " have " +
                         std::to_string(modes) +
                         " zero-energy (hourglass) modes in a patch of its elements beyond the "
                         "rigid motions: their displacements and stresses can be garbage; use a "
                         "type with hourglass control (C3D8R, CAX4R) or full integration");
  }
}

void locking_warnings(const Model& model, const PreparedModel& prepared,
                      std::vector<std::string>& warnings) {
  // Per section and type.
  std::map<std::pair<int, const TElement*>, std::pair<int, const Material*>> locking;
  for (int e = 0; e < model.element_count(); ++e) {
    const int s = model.elements[e].section;
    const Material* material = prepared.material[e];
    if (s < 0 || material == nullptr || !material->poisson || !material->young) continue;
    const TElement& f = *prepared.formulation[e];
    if (*material->poisson < locking_onset(f)) continue;
    // Mean dilatation cures locking of a rule with more than one point; a one-point rule has
    // nothing to average (C3D8R's locking comes from its hourglass control, C3D4's from its one
    // volume constraint per element).
    if (model.sections[s].selective_volumetric && f.rule(RuleKind::Full).size() > 1) continue;
    if (!bulk_dominated(f, *material)) continue;
    auto& entry = locking[{s, &f}];
    ++entry.first;
    entry.second = material;
  }
  for (const auto& [key, entry] : locking) {
    const Section& section = model.sections[key.first];
    const Material& material = *entry.second;
    const TElement& f = *key.second;
    const std::string cure = linear_tetrahedron(f)
                                 ? "use quadratic tetrahedra (C3D10) or bricks with "
                                   "TECHNIQUE=SELECTIVE"
                             : f.rule(RuleKind::Full).size() > 1
                                 ? "add TECHNIQUE=SELECTIVE to the *SOLID SECTION"
                                 : "use C3D8I or C3D20R (TECHNIQUE=SELECTIVE cannot help "
                                   "a one-point rule)";
    warnings.push_back(section.where.file + ":" + std::to_string(section.where.line) + ": " +
                       std::to_string(entry.first) + " " + f.name() + " elements of element set " +
                       section.elset + " lock volumetrically: material " + material.name +
                       " has Poisson's ratio " + format("%g", *material.poisson) + " (" + f.name() +
                       " locks from " + format("%g", locking_onset(f)) + "); " + cure);
  }
}

// Linear tetrahedra where it matters: a section whose elements span fewer than
// kTetrahedraAcross element sizes through its thinnest extent bends with too few constant-strain
// elements across it (docs/elements.md: the SPEC §3.1.1 1b cantilever split into C3D4).
constexpr double kTetrahedraAcross = 4.0;
void tetrahedron_bending_warnings(const Model& model, const PreparedModel& prepared,
                                  std::vector<std::string>& warnings) {
  std::map<int, std::vector<int>> by_section;
  for (int e = 0; e < model.element_count(); ++e)
    if (model.elements[e].section >= 0 && linear_tetrahedron(*prepared.formulation[e]))
      by_section[model.elements[e].section].push_back(e);
  for (const auto& [s, elements] : by_section) {
    double volume = 0.0;
    for (int e : elements) volume += tetrahedron_volume(model, e);
    // The edge of a regular tetrahedron of the mean volume: V = a^3 / (6 sqrt 2).
    const double size = std::cbrt(6.0 * std::sqrt(2.0) * volume / elements.size());
    const double across = thinnest_extent(model, elements) / size;
    if (!(across < kTetrahedraAcross)) continue;
    const Section& section = model.sections[s];
    warnings.push_back(section.where.file + ":" + std::to_string(section.where.line) + ": " +
                       std::to_string(elements.size()) + " linear tetrahedra (" +
                       prepared.formulation[elements.front()]->name() + ") of element set " +
                       section.elset + " have only " + format("%.2g", across) +
                       " element sizes through the thinnest extent of the part: constant-strain "
                       "tetrahedra are far too stiff in bending there; use C3D10 or refine "
                       "across the thickness");
  }
}

void distortion_warnings(const Model& model, const PreparedModel& prepared,
                         std::vector<std::string>& warnings) {
  // The worst element and how many are beyond the ratio.
  std::map<const TElement*, IntegrationRule> rules;
  int distorted = 0, worst = -1;
  double worst_ratio = 1.0;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& f = *prepared.formulation[e];
    if (f.form() == ElementForm::Line) continue;  // a truss has no shape to lose
    auto rule = rules.find(&f);                   // one rule per type, not one per element
    if (rule == rules.end()) rule = rules.emplace(&f, f.rule(RuleKind::Full)).first;
    const double ratio = measure_ratio(model, f, rule->second, e, cross_section_of(model, e));
    if (ratio >= kDistortedRatio) continue;
    ++distorted;
    if (ratio < worst_ratio) worst_ratio = ratio, worst = e;
  }
  if (distorted == 0) return;
  const Element& w = model.elements[worst];
  warnings.push_back(
      std::to_string(distorted) + (distorted == 1 ? " element is" : " elements are") +
      " strongly distorted (det J varies more than 10 times inside the element); worst: "
      "element " +
      std::to_string(w.id) + " (" + w.type + ", line " + std::to_string(w.where.line) +
      "), min/max det J " + format("%.3g", worst_ratio) +
      ": accuracy drops there (constant stress is still exact); reshape or refine");
}

}  // namespace

std::vector<std::string> model_warnings(const Model& model, const PreparedModel& prepared) {
  std::vector<std::string> warnings;
  hourglass_warnings(prepared, warnings);
  locking_warnings(model, prepared, warnings);
  tetrahedron_bending_warnings(model, prepared, warnings);
  // Beams: shear locking of fully integrated slender beams, spurious modes (beam_warnings.hpp).
  for (std::string& warning : beam_warnings(model, prepared))
    warnings.push_back(std::move(warning));
  // Shells: shear locking of thin S8, spurious modes of 2x2 rules (shell_warnings.hpp).
  for (std::string& warning : shell_warnings(model, prepared))
    warnings.push_back(std::move(warning));
  distortion_warnings(model, prepared, warnings);
  return warnings;
}

}  // namespace styk::solver_detail
