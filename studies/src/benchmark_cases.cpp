// The SPEC §3.1 element tests as data. Every thesis number below is copied from SPEC.md (which
// transcribes the thesis' Tab 3.1-3.11 and Tab 3.13); the table each block comes from is cited.
#include "styk/studies/verify/benchmark_cases.hpp"

#include <cmath>

namespace styk::verify {
namespace {

using Kind = Measurement::Kind;

Measurement mean_u(const std::string& set, int component, const std::string& label,
                   double sign = 1.0) {
  return {Kind::MeanComponent, set, component, sign, label};
}

// SPEC §3.1.1: L = 6, W = 0.2, D = 0.1, E = 1e7, nu = 0.3 (builder defaults).
void add_straight_beam(std::vector<BenchmarkCase>& out) {
  struct Row {
    int n;
    std::array<std::optional<double>, kFamilyCount> tension, bending;
  };
  // SPEC §3.1.1 tables 1a and 1b (thesis Tab 3.1 / 3.2): C3D14, C3D21, C3D28, Abaqus C3D8,
  // Abaqus C3D20.
  const Row rows[3] = {
      {6,
       {2.9776e-5, 2.9827e-5, 2.9923e-5, 2.9841e-5, 2.9826e-5},
       {1.3789e-2, 0.1052, 1.6578e-2, 1.0765e-2, 0.1049}},
      {12,
       {2.9900e-5, 2.9910e-5, 3.0009e-5, 2.9916e-5, 2.9910e-5},
       {3.6919e-2, 0.1068, 5.8207e-2, 3.8360e-2, 0.1066}},
      {24,
       {3.0005e-5, 2.9949e-5, 2.9993e-5, 2.9951e-5, 2.9949e-5},
       {8.2537e-2, 0.1074, 9.7594e-2, 0.1070, 0.1074}},
  };
  for (const Row& r : rows) {
    const std::string n = std::to_string(r.n);
    BenchmarkCase c;
    c.section = "§3.1.1";
    c.builder = "straight-beam";
    c.name = "1a-n" + n;
    c.title = "1a tension, " + n + " elements";
    c.params = {{"n", n}, {"load", "tension"}};
    c.measure = mean_u("TIP", 0, "TIP ux (mean)");
    c.theory = 3.0e-5;
    c.theory_source = "PL/(EA)";
    c.thesis = r.tension;
    c.thesis_reference = c.theory;
    // Tab 3.13 "1a": A for every element at every n; the 6-element mesh is the row shown here.
    if (r.n == 6) {
      c.grade_row = "1a";
      c.thesis_grades = "AAAAA";
    }
    out.push_back(c);
  }
  for (const Row& r : rows) {
    const std::string n = std::to_string(r.n);
    BenchmarkCase c;
    c.section = "§3.1.1";
    c.builder = "straight-beam";
    c.name = "1b-n" + n;
    c.title = "1b bending, " + n + " elements";
    c.params = {{"n", n}, {"load", "bending"}};
    c.measure = mean_u("TIP", 2, "TIP uz (mean)");
    c.theory = 0.108;
    c.theory_source = "PL^3/(3EI), P = 1 (SPEC corrects the OCR)";
    c.thesis = r.bending;
    c.thesis_reference = c.theory;
    // SPEC §3.1.9 (Tab 3.13): 1b 6x1 E B E E B, 1b 24x1 D A B A A.
    if (r.n == 6) {
      c.grade_row = "1b 6x1";
      c.thesis_grades = "EBEEB";
    } else if (r.n == 24) {
      c.grade_row = "1b 24x1";
      c.thesis_grades = "DABAA";
    }
    out.push_back(c);
  }
}

// SPEC §3.1.2: 10 x 2 x 2, E = 1500, nu = 0.3, 5 elements, regular and distorted (stand-in).
void add_beam_10x2x2(std::vector<BenchmarkCase>& out) {
  struct Row {
    const char* mesh;
    const char* load;
    std::array<std::optional<double>, kFamilyCount> thesis;
  };
  // SPEC §3.1.2 table (thesis Tab 3.3 / 3.4).
  const Row rows[4] = {
      {"regular", "tension", {1.7159e-3, 1.6560e-3, 1.6643e-3, 1.6553e-3, 1.6559e-3}},
      {"distorted", "tension", {1.6961e-3, 1.6582e-3, 1.6605e-3, 1.6628e-3, 1.6586e-3}},
      {"regular", "bending", {9.2718e-2, 0.1010, 9.3557e-2, 0.1206, 0.1005}},
      {"distorted", "bending", {7.3810e-2, 0.1008, 9.6603e-2, 8.9979e-2, 0.1004}},
  };
  for (const Row& r : rows) {
    const bool tension = std::string(r.load) == "tension";
    const bool distorted = std::string(r.mesh) == "distorted";
    BenchmarkCase c;
    c.section = "§3.1.2";
    c.builder = "beam-10x2x2";
    c.name = std::string(tension ? "2a-" : "2b-") + r.mesh;
    c.title = std::string(tension ? "2a tension, " : "2b bending, ") + r.mesh + " mesh";
    c.params = {{"mesh", r.mesh}, {"load", r.load}};
    c.measure = mean_u("TIP", tension ? 0 : 2, tension ? "TIP ux (mean)" : "TIP uz (mean)");
    c.theory = tension ? 1.6667e-3 : 0.1;
    c.theory_source = tension ? "PL/(EA)" : "thesis (Choi & Chung), P = 0.6";
    c.thesis = r.thesis;
    c.thesis_reference = c.theory;
    // Tab 3.13's 2a / 2b rows are the distorted mesh: recomputing the grades from the thesis'
    // values gives A A A A A and D A B C A only there (regular 2a C3D14 is 2.95 %, B).
    if (distorted) {
      c.grade_row = tension ? "2a" : "2b";
      c.thesis_grades = tension ? "AAAAA" : "DABCA";
      c.stand_in = true;
      c.note =
          "The distorted node positions are only in a lost figure; the mesh is SPEC's "
          "stand-in, so the thesis' values are for another distortion.";
    }
    out.push_back(c);
  }
}

// SPEC §3.1.3: the thesis' Krishnamoorthy beam is only in a lost figure; stand-in: the
// MacNeal-Harder curved beam (6 elements, E = 1e7, nu = 0.25).
void add_curved_beam(std::vector<BenchmarkCase>& out) {
  BenchmarkCase a;
  a.section = "§3.1.3";
  a.builder = "curved-beam";
  a.name = "3a";
  a.title = "3a curved beam, in-plane (stand-in)";
  a.params = {{"load", "inplane"}};
  a.measure = mean_u("TIP", 1, "TIP uy (mean)");
  a.theory = 0.08734;
  a.theory_source = "MacNeal-Harder";
  // SPEC §3.1.3 (thesis Tab 3.5): theory -0.2623; C3D14 -0.1673, C3D21 -0.2556, C3D28 -0.2339,
  // C3D8 -0.1428, C3D20 -0.2554. Tab 3.13: 3a D B B D A.
  a.thesis = {-0.1673, -0.2556, -0.2339, -0.1428, -0.2554};
  a.thesis_reference = -0.2623;
  a.grade_row = "3a";
  a.thesis_grades = "DBBDA";
  a.stand_in = true;
  a.note =
      "Stand-in geometry (SPEC §3.1.3): the thesis' values are for the Krishnamoorthy beam "
      "(theory -0.2623) and are not comparable number for number.";
  out.push_back(a);

  BenchmarkCase b = a;
  b.name = "3b";
  b.title = "3b curved beam, out-of-plane (stand-in)";
  b.params = {{"load", "outofplane"}};
  b.measure = mean_u("TIP", 2, "TIP uz (mean)");
  b.theory = 0.5022;
  // SPEC §3.1.3 (thesis Tab 3.6): no theory value printed; C3D14 -0.1951, C3D21 -0.2267,
  // C3D28 -0.2088, C3D8 -0.2129, C3D20 -0.2187. Not a row of Tab 3.13.
  b.thesis = {-0.1951, -0.2267, -0.2088, -0.2129, -0.2187};
  b.thesis_reference.reset();
  b.grade_row.clear();
  b.thesis_grades.clear();
  out.push_back(b);
}

// SPEC §3.1.4: twisted beam 12 x 1.1 x 0.32, E = 29e6, nu = 0.22, unit in-plane tip load.
void add_twisted_beam(std::vector<BenchmarkCase>& out) {
  struct Row {
    int n;
    const char* grades;
    std::array<std::optional<double>, kFamilyCount> thesis;
  };
  // SPEC §3.1.4 table (thesis Tab 3.7; printed negative, P = -1) and Tab 3.13 "4 12x2 E B D E B",
  // "4 24x2 D B C E B".
  const Row rows[2] = {
      {12, "EBDEB", {1.3006e-3, 4.8635e-3, 3.2358e-3, 1.1791e-3, 4.8633e-3}},
      {24, "DBCEB", {2.9475e-3, 4.8938e-3, 4.4968e-3, 2.6071e-3, 4.8937e-3}},
  };
  for (const Row& r : rows) {
    const std::string n = std::to_string(r.n);
    BenchmarkCase c;
    c.section = "§3.1.4";
    c.builder = "twisted-beam";
    c.name = "4-" + n + "x2";
    c.title = "4 twisted beam, " + n + "x2";
    c.params = {{"n", n}, {"across", "2"}, {"load", "inplane"}};
    c.measure = mean_u("TIP", 2, "TIP uz (mean)");
    c.theory = 5.424e-3;
    c.theory_source = "MacNeal-Harder";
    c.thesis = r.thesis;
    c.thesis_reference = c.theory;
    c.grade_row = "4 " + n + "x2";
    c.thesis_grades = r.grades;
    out.push_back(c);
  }
}

// SPEC §3.1.5: plate 400 x 400 x 40, E = 2000, nu = 0.15, P = 16 at the top centre. The thesis'
// text calls the plate simply supported (β1 = 0.01353 is a simple-support coefficient) while SPEC
// reads "edge nodes fully fixed"; the graded rows use the simple support, the as-built deck
// (clamped side faces) is listed for the record (docs/verification.md §3.1.5).
void add_thick_plate(std::vector<BenchmarkCase>& out) {
  struct Row {
    int n;
    const char* grades;
    std::array<std::optional<double>, kFamilyCount> thesis;
  };
  // SPEC §3.1.5 table (thesis Tab 3.8) and Tab 3.13 "5 6x6 E A C E A", "5 10x10 E B A D B".
  const Row rows[2] = {
      {6, "EACEA", {1.3195e-3, 3.2761e-3, 2.8129e-3, 1.1447e-3, 3.2599e-3}},
      {10, "EBADB", {1.6601e-3, 3.5152e-3, 3.2894e-3, 1.8672e-3, 3.4835e-3}},
  };
  for (const bool simple : {true, false})
    for (const Row& r : rows) {
      const std::string n = std::to_string(r.n);
      BenchmarkCase c;
      c.section = "§3.1.5";
      c.builder = "thick-plate";
      c.name = "5-" + n + "x" + n + (simple ? "" : "-clamped");
      c.title = "5 thick plate, " + n + "x" + n +
                (simple ? ", simply supported (bottom edges)" : ", side faces clamped");
      c.params = {{"n", n}};
      c.support = simple ? Support::PlateSimplySupported : Support::AsBuilt;
      c.measure = mean_u("BOTCENTRE", 2, "bottom-centre deflection -uz", -1.0);
      c.theory = 0.003322;
      c.theory_source = "published, simply supported (β1 = 0.01353)";
      c.thesis = r.thesis;
      c.thesis_reference = c.theory;
      if (simple) {
        c.grade_row = "5 " + n + "x" + n;
        c.thesis_grades = r.grades;
      }
      c.note =
          "The thesis' support is not recoverable: its text says simply supported, SPEC "
          "says edge nodes fully fixed; neither reproduces its values (see "
          "docs/verification.md §3.1.5).";
      out.push_back(c);
    }
}

// SPEC §3.1.6: the thesis' shell is only in a lost figure; stand-in: MacNeal-Harder hemisphere.
void add_hemisphere(std::vector<BenchmarkCase>& out) {
  BenchmarkCase c;
  c.section = "§3.1.6";
  c.builder = "hemisphere";
  c.name = "6";
  c.title = "6 hemispherical shell (stand-in)";
  c.measure = mean_u("LOADA", 0, "LOADA ux (mean)");
  c.theory = 0.094;
  c.theory_source = "MacNeal-Harder";
  // SPEC §3.1.6: C3D14 -5.9177e-2, C3D21 -6.2835e-2, C3D28 -5.9458e-2, C3D8 -5.6913e-2,
  // C3D20 -6.2928e-2, S8R -5.9363e-2 (no theory; the Tab 3.13 grades "6 A B A B B" follow from
  // grading against S8R).
  c.thesis = {-5.9177e-2, -6.2835e-2, -5.9458e-2, -5.6913e-2, -6.2928e-2};
  c.thesis_reference = -5.9363e-2;
  c.grade_row = "6";
  c.thesis_grades = "ABABB";
  c.stand_in = true;
  c.note =
      "Stand-in geometry (SPEC §3.1.6): the thesis' 1/8 sphere is in a lost figure; its "
      "values are graded against its S8R result -5.9363e-2.";
  out.push_back(c);
}

// SPEC §3.1.7: thick-walled cylinder R1 = 3, R2 = 9, E = 1000, p = 1, plane strain.
void add_thick_cylinder(std::vector<BenchmarkCase>& out) {
  struct Row {
    const char* nu;
    std::array<std::optional<double>, kFamilyCount> thesis;
  };
  // SPEC §3.1.7 table (thesis Tab 3.10): C3D14, C3D21, C3D28 (no C3D8 / C3D20 columns; CPE8
  // 5.0386e-3 / 5.0471e-3 / 4.9344e-3). Tab 3.13 "7 nu=0.49 B A A".
  const Row rows[3] = {
      {"0.49", {4.8973e-3, 5.0329e-3, 5.0359e-3, std::nullopt, std::nullopt}},
      {"0.499", {4.7173e-3, 4.9917e-3, 4.9987e-3, std::nullopt, std::nullopt}},
      {"0.4999", {4.6542e-3, 4.4513e-3, 4.5713e-3, std::nullopt, std::nullopt}},
  };
  for (const Row& r : rows) {
    const double nu = std::stod(r.nu), r1 = 3, r2 = 9, E = 1000, p = 1;
    BenchmarkCase c;
    c.section = "§3.1.7";
    c.builder = "thick-cylinder";
    c.name = std::string("7-nu") + r.nu;
    c.title = std::string("7 thick cylinder, ν = ") + r.nu;
    c.params = {{"poisson", r.nu}};
    c.measure = {Kind::MeanRadial, "INNER", 0, 1.0, "INNER radial u (mean)"};
    c.theory =
        (1 + nu) * p * r1 * r1 / (E * (r2 * r2 - r1 * r1)) * (r2 * r2 / r1 + (1 - 2 * nu) * r1);
    c.theory_source = "Lamé, plane strain";
    c.thesis = r.thesis;
    c.thesis_reference = c.theory;
    if (std::string(r.nu) == "0.49") {
      c.grade_row = "7 ν=0.49";
      c.thesis_grades = "BAA--";
    }
    out.push_back(c);
  }
}

// SPEC §3.1.8: patch test, E = 1e6, nu = 0.25: sigma = 2000, tau = 400 everywhere.
void add_patch_test(std::vector<BenchmarkCase>& out) {
  BenchmarkCase c;
  c.section = "§3.1.8";
  c.builder = "patch-test";
  c.name = "8-patch";
  c.title = "8 patch test";
  c.measure = {Kind::WorstPatchStress, "", 0, 1.0, "worst integration-point stress"};
  c.theory = 2000.0;
  c.theory_source = "constant strain 1e-3";
  // SPEC §3.1.8: sigma = 2000 published for C3D14 alone, C3D21 + C3D20 and C3D28 + C3D20;
  // Tab 3.13 "8 patch A A A A A".
  c.thesis = {2000.0, 2000.0, 2000.0, std::nullopt, std::nullopt};
  c.thesis_reference = c.theory;
  c.grade_row = "8 patch";
  c.thesis_grades = "AAAAA";
  out.push_back(c);
}

}  // namespace

int family_index(const std::string& family) {
  for (int i = 0; i < kFamilyCount; ++i)
    if (family == kElementFamilies[i]) return i;
  return -1;
}

std::vector<BenchmarkCase> benchmark_cases() {
  std::vector<BenchmarkCase> out;
  add_straight_beam(out);
  add_beam_10x2x2(out);
  add_curved_beam(out);
  add_twisted_beam(out);
  add_thick_plate(out);
  add_hemisphere(out);
  add_thick_cylinder(out);
  add_patch_test(out);
  return out;
}

const BenchmarkCase* find_case(const std::vector<BenchmarkCase>& cases, const std::string& name) {
  for (const BenchmarkCase& c : cases)
    if (c.name == name) return &c;
  return nullptr;
}

double relative_error(double value, double reference) {
  return std::abs(std::abs(value) - std::abs(reference)) / std::abs(reference);
}

char grade(double value, double reference) {
  const double error = relative_error(value, reference);
  if (error < 0.02) return 'A';
  if (error < 0.10) return 'B';
  if (error < 0.20) return 'C';
  if (error < 0.50) return 'D';
  return 'E';
}

}  // namespace styk::verify
