// The SPEC §3.1 element tests (MacNeal-Harder style) as data: which builder and parameters make
// the model, which quantity is measured, the reference value it is graded against (SPEC Tab
// 3.12), and the thesis' published values and Tab 3.13 grades per element family. The numbers are
// copied from SPEC.md (the thesis' own tables) in src/benchmark_cases.cpp.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace styk::verify {

// The element families of the thesis' Tab 3.13, in its column order.
constexpr int kFamilyCount = 5;
inline constexpr std::array<const char*, kFamilyCount> kElementFamilies = {
    "C3D14", "C3D21", "C3D28", "C3D8", "C3D20"};
// Index of `family` in kElementFamilies, or -1.
int family_index(const std::string& family);

// What is read from the solution.
struct Measurement {
  enum class Kind {
    MeanComponent,     // mean of displacement component `component` over node set `node_set`
    MeanRadial,        // mean radial displacement (about the z axis) over `node_set`
    WorstPatchStress,  // the integration-point stress component farthest (relatively) from the
                       // constant-strain patch stress (sigma = 2000, tau = 400); reported on
                       // the sigma = 2000 scale: 2000 (1 + worst signed relative deviation)
  };
  Kind kind = Kind::MeanComponent;
  std::string node_set;
  int component = 0;  // 0 = x
  double sign = 1.0;  // -1 where the thesis reports a downward deflection as positive
  std::string label;  // for the tables, e.g. "TIP uz (mean)"
};

// How the builder's boundary conditions are used.
enum class Support {
  AsBuilt,  // the builder's deck unchanged
  // SPEC §3.1.5 as the thesis' text states it ("simply supported on all edges" [21]): the
  // builder's clamped side faces are replaced by w = 0 on the four bottom edge lines, plus the
  // three in-plane rigid-body constraints (u = v = 0 at the corner (0, 0, 0), v = 0 at (a, 0, 0)).
  PlateSimplySupported,
};

struct BenchmarkCase {
  std::string name;                           // unique, e.g. "1b-n6"; `styk verify --case NAME`
  std::string section;                        // "§3.1.1"
  std::string title;                          // "1b bending, 6 elements"
  std::string builder;                        // mesher builder (styk mesh --list)
  std::map<std::string, std::string> params;  // builder parameters besides --element
  Support support = Support::AsBuilt;
  Measurement measure;
  double theory = 0.0;        // what our values are graded against
  std::string theory_source;  // e.g. "beam theory PL^3/(3EI)"
  // The thesis' values per family (kElementFamilies order); nullopt where not published.
  std::array<std::optional<double>, kFamilyCount> thesis{};
  // What the thesis graded its own values against (differs from `theory` for stand-ins: the
  // thesis' model is another geometry). nullopt where the thesis gives none.
  std::optional<double> thesis_reference;
  // Tab 3.13 row label ("1b 6x1") and the thesis' grades ('-' = not graded); empty if the case
  // is not a row of Tab 3.13.
  std::string grade_row;
  std::string thesis_grades;
  // True where SPEC prescribes a stand-in model: the thesis' values belong to another geometry
  // and are printed for the record only.
  bool stand_in = false;
  std::string note;  // shown under the case table
};

// Every case, in SPEC order.
std::vector<BenchmarkCase> benchmark_cases();

// The case called `name`, or nullptr.
const BenchmarkCase* find_case(const std::vector<BenchmarkCase>& cases, const std::string& name);

// SPEC §3.1 Tab 3.12: A < 2 %, B < 10 %, C < 20 %, D < 50 %, E otherwise (relative error of
// |value| against |reference|; the thesis' sign conventions differ between tables).
char grade(double value, double reference);
double relative_error(double value, double reference);

}  // namespace styk::verify
