#include "shell_locking.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "section_extent.hpp"
#include "warning_format.hpp"

namespace styk::solver_detail {
namespace {

// The shear-locking law f = C (h / t)^2 (h / L)^p of a serendipity shell and the figures it is
// fitted to. Measured on the uniformly loaded, simply supported square plate of SPEC §7.3
// Tab 7.1b as a quarter of extent L = 0.5 (tests/verification/spec_7_3_plates_test.cpp,
// shell_warnings_test.cpp and docs/stability.md "thin-plate"), f = w_Mindlin / w - 1 at the
// centre:
//   S8  (3x3): 2x2 elements (h / L = 0.5): f = 0.089 at h / t = 25, 7.0 at 250;
//              4x4 (h / L = 0.25): 0.084 at 125, 8.2 at 1250;
//              8x8 (h / L = 0.125): 0.117 at 625, 1.31 at 2083, 11.8 at 6250;
//   S8R (2x2): 2x2: 0.011 at 25, 1.18 at 250; 4x4: 0.0041 at 125, 0.46 at 1250;
//              8x8: 0.017 at 2083, 0.171 at 6250, 2.0 at 20833.
// On each mesh f grows as (h / t)^2 once locking dominates; at fixed h / t it falls 21 and 17
// times (S8) and 65 and 62 times (S8R) as h halves: p = 4.25 and 6, C within 10 % on all three.
struct LockingLaw {
  double coefficient;
  double exponent;
  const char* fitted;  // the measurements, for the message
  const char* remedy;
};

constexpr LockingLaw kS8Locking{
    2.1e-3, 4.25,
    "SPEC §7.3 Tab 7.1b's plate: 8 % at size / t 25 and 87 % at 250 with elements half the "
    "plate's extent, 8 % at 125 and 89 % at 1250 with a quarter, 11 % at 625 and 92 % at 6250 "
    "with an eighth",
    "reduced integration (S8R), the 9-node Lagrange shell (S9 or S9R) or more elements"};
constexpr LockingLaw kS8RLocking{
    1.16e-3, 6.0,
    "SPEC §7.3 Tab 7.1b's plate: 1 % at size / t 25 and 54 % at 250 with elements half the "
    "plate's extent, 32 % at 1250 with a quarter, 15 % at 6250 with an eighth",
    "the 9-node Lagrange shell (S9R or S9) or more elements"};

// Warned from a deflection short by 10 %: f / (1 + f) >= 0.1.
constexpr double kLockingWarned = 1.0 / 9.0;

// A Kirchhoff shell misses the shear deflection, 5.2 (t / a)^2 of the bending deflection of a
// simply supported plate of span a (the Mindlin series, SPEC §7.3; measured with STRI3 on the
// quarter plate of docs/stability.md: 4.9 % short at t / a = 0.1, 17 % at 0.2). Warned from
// t / L = 0.3, L the section's extent: a symmetric quarter (span 2 L) is then 10.5 % short; a
// whole plate (span L) passes 10 % from t / L = 0.145 on, unwarned below 0.3 (a threshold
// there would warn of quarter models that are accurate).
constexpr double kKirchhoffThickWarned = 0.3;

bool is_shell(const TElement& element) {
  return element.section_measure() == SectionMeasure::Shell;
}

// The serendipity shell's locking law for the rule it runs with, or null: the 3x3 rule (S8) or
// the 2x2 (S8R, and S8 asked for its reduced rule); S8R's own "full" rule is its 2x2.
const LockingLaw* locking_law(const TElement& element, RuleKind kind) {
  if (!is_shell(element) || element.node_count() != 8) return nullptr;
  return element.rule(kind).size() > element.rule(RuleKind::Reduced).size() ? &kS8Locking
                                                                            : &kS8RLocking;
}

std::string where(const Section& section) {
  return section.where.file + ":" + std::to_string(section.where.line) + ": ";
}

}  // namespace

double shell_element_size(const Model& model, int e) {
  const int* nodes = model.element_nodes(e);
  const int corners = model.elements[e].node_count == 3 ? 3 : 4;
  double size = 0.0;
  for (int k = 0; k < corners; ++k) {
    const Vec3& a = model.coords[nodes[k]];
    const Vec3& b = model.coords[nodes[(k + 1) % corners]];
    size = std::max(size, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  return size;
}

std::vector<std::string> shell_locking_warnings(const Model& model, const PreparedModel& prepared) {
  struct Worst {
    int count = 0;
    int element = -1;
    double factor = 0.0, slenderness = 0.0;
    const TElement* type = nullptr;
    const LockingLaw* law = nullptr;
  };
  const std::vector<double> extent = section_extents(model);
  std::map<std::pair<int, const TElement*>, Worst> locking;
  for (int e = 0; e < model.element_count(); ++e) {
    const LockingLaw* law = locking_law(*prepared.formulation[e], prepared.rule_kind[e]);
    const int s = model.elements[e].section;
    if (law == nullptr || extent[s] <= 0.0) continue;
    const double h = shell_element_size(model, e);
    const double slenderness = h / model.sections[s].thickness.value_or(1.0);
    const double f =
        law->coefficient * slenderness * slenderness * std::pow(h / extent[s], law->exponent);
    if (f < kLockingWarned) continue;
    Worst& w = locking[{s, prepared.formulation[e]}];
    ++w.count;
    if (w.element < 0 || f > w.factor)
      w = Worst{w.count, e, f, slenderness, prepared.formulation[e], law};
  }
  std::vector<std::string> warnings;
  for (const auto& [key, w] : locking) {
    const Section& section = model.sections[key.first];
    warnings.push_back(
        where(section) + std::to_string(w.count) + " " + w.type->name() +
        " elements of element set " + section.elset + " are thin: element size / thickness up to " +
        format("%.3g", w.slenderness) + " (element " +
        std::to_string(model.elements[w.element].id) + ") on a shell " +
        format("%.3g", extent[key.first]) + " across, where the " +
        (w.law == &kS8Locking ? "fully integrated" : "reduced-integration") +
        " 8-node serendipity shell locks in shear: its deflection estimated " +
        format("%.0f", 100.0 * w.factor / (1.0 + w.factor)) +
        " % short (stiffening 1 + f, f = " + format("%.3g", w.law->coefficient) +
        " (size / t)^2 (size / extent)^" + format("%g", w.law->exponent) + " = " +
        format("%.3g", w.factor) + ", fitted to " + w.law->fitted + "); remedy: " + w.law->remedy);
  }
  return warnings;
}

std::vector<std::string> thick_kirchhoff_shell_warnings(const Model& model,
                                                        const PreparedModel& prepared) {
  const std::vector<double> extent = section_extents(model);
  std::map<int, int> count_of;  // section -> STRI3 elements
  for (int e = 0; e < model.element_count(); ++e)
    if (prepared.formulation[e]->name() == "STRI3") ++count_of[model.elements[e].section];
  std::vector<std::string> warnings;
  for (const auto& [s, count] : count_of) {
    const Section& section = model.sections[s];
    const double ratio = section.thickness.value_or(0.0) / extent[s];
    if (!(extent[s] > 0.0) || ratio < kKirchhoffThickWarned) continue;
    warnings.push_back(
        where(section) + std::to_string(count) + " STRI3 elements of element set " + section.elset +
        " are thick for a Kirchhoff (thin) shell: thickness / extent " + format("%.3g", ratio) +
        " (thickness " + format("%.3g", *section.thickness) + ", the shell " +
        format("%.3g", extent[s]) +
        " across); STRI3 has no transverse shear deflection, which adds about 5.2 (t / span)^2 "
        "to the bending deflection of a simply supported plate (SPEC §7.3; 17 % short at "
        "t / span 0.2); remedy: a Reissner-Mindlin shell (S4R, S8R, S9R)");
  }
  return warnings;
}

}  // namespace styk::solver_detail
