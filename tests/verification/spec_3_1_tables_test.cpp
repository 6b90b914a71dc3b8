// SPEC §3.1.1-§3.1.9: the element tests of the thesis for every element family, run through the
// same case table as `styk verify --table 3.13` (mesher/verify). Each test states the expected
// value, its source and the tolerance. Where the thesis' value cannot be reproduced the reason is
// in docs/verification.md ("SPEC §3.1.2-§3.1.9") and the test asserts what is justified instead:
// our value against CalculiX 2.20 on the identical deck (written by write_inp, solved by `ccx` in
// a scratch directory), against our C3D20 or against theory.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/studies/verify/report.hpp"
#include "support/ccx_runner.hpp"

namespace styk::verify {
namespace {

class Spec3_1 : public ::testing::Test {
 protected:
  void SetUp() override {
    full_ = test::registry_with_plugins();
    ASSERT_TRUE(full_->diagnostics.empty()) << full_->diagnostics.front().message;
    cases_ = benchmark_cases();
  }

  const BenchmarkCase& bench(const std::string& name) const {
    const BenchmarkCase* c = find_case(cases_, name);
    if (!c) throw std::invalid_argument("no case " + name);
    return *c;
  }
  double ours(const std::string& name, const std::string& family) const {
    return run_case(bench(name), family, full_->registry);
  }
  double thesis(const std::string& name, const std::string& family) const {
    return bench(name).thesis[family_index(family)].value();
  }

  // The case's deck for `family`, solved by CalculiX 2.20 (`ccx` on PATH), measured as ours.
  double calculix(const std::string& name, const std::string& family) const {
    const BenchmarkCase& c = bench(name);
    const Model model = build_case_model(c, family, full_->registry);
    const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / "tests" /
                                      "verification" / "ccx_spec_3_1" / (name + "_" + family);
    std::filesystem::create_directories(dir);
    {
      std::ofstream deck(dir / "job.inp");
      write_inp(model, deck);
    }
    if (test::run_ccx(dir, "job").exit_code != 0)
      throw std::runtime_error("ccx failed in " + dir.string() + " (" + test::kCcxMissing + "?)");
    std::ifstream dat(dir / "job.dat");
    const std::vector<DatDisplacements> blocks = parse_dat_displacements(dat);
    if (blocks.empty())
      throw std::runtime_error("no displacements in " + (dir / "job.dat").string());
    std::vector<Vec3> U(model.node_count(), Vec3{0, 0, 0});
    for (const auto& [id, u] : blocks.back().u) U.at(model.node_index(id)) = u;
    return measure_displacements(c, model, U);
  }

  std::unique_ptr<test::FullRegistry> full_;
  std::vector<BenchmarkCase> cases_;
};

TEST_F(Spec3_1, Tension1aContactElementsWithinTwoPercentOfThesis) {
  // SPEC §3.1.1 1a (thesis Tab 3.1): C3D14 2.9776e-5 / 2.9900e-5 / 3.0005e-5, C3D21 2.9827e-5 /
  // 2.9910e-5 / 2.9949e-5, C3D28 2.9923e-5 / 3.0009e-5 / 2.9993e-5 (n = 6 / 12 / 24):
  // tolerance 2 % (measured: within 0.3 %). Abaqus C3D20 2.9826e-5 / 2.9910e-5 / 2.9949e-5:
  // tolerance 0.01 % (four printed digits).
  for (const char* n : {"6", "12", "24"}) {
    const std::string name = std::string("1a-n") + n;
    for (const char* family : {"C3D14", "C3D21", "C3D28"})
      EXPECT_NEAR(ours(name, family), thesis(name, family), 0.02 * thesis(name, family))
          << name << " " << family;
    EXPECT_NEAR(ours(name, "C3D20"), thesis(name, "C3D20"), 1e-4 * thesis(name, "C3D20")) << name;
  }
}

TEST_F(Spec3_1, Bending1bAgainstThesis) {
  // SPEC §3.1.1 1b (thesis Tab 3.2), theory 0.108.
  // C3D21 0.1052 / 0.1068 / 0.1074: tolerance 2 % (measured within 0.05 %).
  // Abaqus C3D20 0.1049 / 0.1066 / 0.1074: tolerance 0.05 % (four printed digits).
  // C3D14 3.6919e-2 (n = 12) and 8.2537e-2 (n = 24): tolerance 2 % (measured 0.003 %).
  for (const char* n : {"6", "12", "24"}) {
    const std::string name = std::string("1b-n") + n;
    EXPECT_NEAR(ours(name, "C3D21"), thesis(name, "C3D21"), 0.02 * thesis(name, "C3D21")) << name;
    EXPECT_NEAR(ours(name, "C3D20"), thesis(name, "C3D20"), 5e-4 * thesis(name, "C3D20")) << name;
  }
  for (const char* name : {"1b-n12", "1b-n24"})
    EXPECT_NEAR(ours(name, "C3D14"), thesis(name, "C3D14"), 0.02 * thesis(name, "C3D14")) << name;
}

TEST_F(Spec3_1, Bending1bWhereTheThesisCannotBeReproduced) {
  // SPEC §3.1.1 1b, C3D14 n = 6: the thesis prints 1.3789e-2, ours is 1.073e-2 although n = 12
  // and 24 agree to 5 digits (same element, load and measure), so the printed n = 6 value is not
  // reproducible (docs/verification.md). Asserted instead: C3D14 contains the C3D8 space, so it
  // lies between our plain C3D8 and theory, and the plain C3D8 equals CalculiX's C3D8 on the
  // same deck to 0.01 %.
  const double c3d8 = ours("1b-n6", "C3D8");
  EXPECT_NEAR(c3d8, calculix("1b-n6", "C3D8"), 1e-4 * c3d8);
  const double c3d14 = ours("1b-n6", "C3D14");
  EXPECT_GT(c3d14, c3d8);
  EXPECT_LT(c3d14, 0.108);
  // C3D28: the thesis' C3D28 (Buczkowski & Gabbert 2004, not published in the thesis) locks in
  // bending (1.6578e-2 / 5.8207e-2 / 9.7594e-2); ours is the quadratically complete element of
  // elements-ref §4 and cannot lock like a linear brick. Asserted: within 2 % of the thesis' Abaqus
  // C3D20 column 0.1049 / 0.1066 / 0.1074 (measured within 0.25 %), grade B / A / A.
  for (const char* n : {"6", "12", "24"}) {
    const std::string name = std::string("1b-n") + n;
    EXPECT_NEAR(ours(name, "C3D28"), thesis(name, "C3D20"), 0.02 * thesis(name, "C3D20")) << name;
  }
}

TEST_F(Spec3_1, Beam10x2x2RegularMesh) {
  // SPEC §3.1.2 regular mesh (thesis Tab 3.3 / 3.4): Abaqus C3D20 2a 1.6559e-3, 2b 0.1005;
  // C3D21 2a 1.6560e-3, 2b 0.1010: tolerance 2 % (measured -0.34 % / -1.73 %, -0.34 % / -1.56 %).
  // The distorted mesh is SPEC's stand-in (lost figure): not compared number for number.
  for (const char* name : {"2a-regular", "2b-regular"})
    for (const char* family : {"C3D20", "C3D21"})
      EXPECT_NEAR(ours(name, family), thesis(name, family), 0.02 * thesis(name, family))
          << name << " " << family;
}

TEST_F(Spec3_1, TwistedBeam) {
  // SPEC §3.1.4, theory 5.424e-3. The thesis' C3D21 (4.8635e-3 / 4.8938e-3) and its Abaqus C3D20
  // (4.8633e-3 / 4.8937e-3) both sit 10.4 % below our C3D20, which equals CalculiX's C3D20 on the
  // same deck: the thesis' model differs (its mesh is only in a lost figure), not the element
  // (docs/verification.md). Asserted:
  //  - our C3D20 = CalculiX C3D20, tolerance 0.01 %;
  //  - C3D21 and C3D28 (+ C3D20 upper row) within 2 % of theory (measured 0.9 % / 0.7 % at 12x2);
  //  - the thesis' C3D21 / C3D20 ratio (1.00004 / 1.00002) reproduced to 0.5 %.
  for (const char* name : {"4-12x2", "4-24x2"}) {
    const double c3d20 = ours(name, "C3D20");
    EXPECT_NEAR(c3d20, calculix(name, "C3D20"), 1e-4 * c3d20) << name;
    EXPECT_NEAR(ours(name, "C3D21"), 5.424e-3, 0.02 * 5.424e-3) << name;
    EXPECT_NEAR(ours(name, "C3D28"), 5.424e-3, 0.02 * 5.424e-3) << name;
    const double thesis_ratio = thesis(name, "C3D21") / thesis(name, "C3D20");
    EXPECT_NEAR(ours(name, "C3D21") / c3d20, thesis_ratio, 5e-3) << name;
  }
  // C3D14 (thesis 1.3006e-3 / 2.9475e-3, ours 18 % / 31 % higher) contains the C3D8 space and is
  // contained in no quadratic one: it must lie between our C3D8 (= CalculiX C3D8, 0.01 %) and
  // our C3D20.
  const double c3d8 = ours("4-12x2", "C3D8");
  EXPECT_NEAR(c3d8, calculix("4-12x2", "C3D8"), 1e-4 * c3d8);
  EXPECT_GT(ours("4-12x2", "C3D14"), c3d8);
  EXPECT_LT(ours("4-12x2", "C3D14"), ours("4-12x2", "C3D20"));
}

TEST_F(Spec3_1, ThickPlate) {
  // SPEC §3.1.5: neither support reading reproduces the thesis (docs/verification.md): simply
  // supported bottom edges give C3D20 3.03e-3 (thesis Abaqus 3.2599e-3 / 3.4835e-3), clamped side
  // faces 1.43e-3. Asserted for both supports: our C3D20 = CalculiX C3D20 on the same deck
  // (0.01 %); C3D21 and C3D28 within 2 % of our C3D20 (same quadratic space off the contact
  // face; measured within 0.7 %); our C3D8 = CalculiX C3D8 (0.01 %, 6x6).
  for (const char* name : {"5-6x6", "5-10x10", "5-6x6-clamped", "5-10x10-clamped"}) {
    const double c3d20 = ours(name, "C3D20");
    EXPECT_NEAR(c3d20, calculix(name, "C3D20"), 1e-4 * c3d20) << name;
    EXPECT_NEAR(ours(name, "C3D21"), c3d20, 0.02 * c3d20) << name;
    EXPECT_NEAR(ours(name, "C3D28"), c3d20, 0.02 * c3d20) << name;
  }
  const double c3d8 = ours("5-6x6", "C3D8");
  EXPECT_NEAR(c3d8, calculix("5-6x6", "C3D8"), 1e-4 * c3d8);
}

TEST_F(Spec3_1, ThickCylinder) {
  // SPEC §3.1.7 (thesis Tab 3.10): C3D21 5.0329e-3 / 4.9917e-3 / 4.4513e-3 and C3D28 5.0359e-3 /
  // 4.9987e-3 / 4.5713e-3 at nu = 0.49 / 0.499 / 0.4999: tolerance 2 % (measured within 0.81 % /
  // 1.83 %); C3D14 4.8973e-3 at nu = 0.49: tolerance 2 % (measured 0.46 %).
  for (const char* name : {"7-nu0.49", "7-nu0.499", "7-nu0.4999"})
    for (const char* family : {"C3D21", "C3D28"})
      EXPECT_NEAR(ours(name, family), thesis(name, family), 0.02 * thesis(name, family))
          << name << " " << family;
  EXPECT_NEAR(ours("7-nu0.49", "C3D14"), thesis("7-nu0.49", "C3D14"),
              0.02 * thesis("7-nu0.49", "C3D14"));
  // C3D20 has no thesis column: our C3D20 = CalculiX C3D20 on the same deck (0.01 %) and within
  // 0.2 % of Lame at nu = 0.49 (5.0399e-3).
  const double c3d20 = ours("7-nu0.49", "C3D20");
  EXPECT_NEAR(c3d20, calculix("7-nu0.49", "C3D20"), 1e-4 * c3d20);
  EXPECT_NEAR(c3d20, bench("7-nu0.49").theory, 2e-3 * bench("7-nu0.49").theory);
  // C3D14 at nu = 0.499 / 0.4999 locks more than the thesis' (ours 4.28e-3 / 1.84e-3, thesis
  // 4.7173e-3 / 4.6542e-3; docs/verification.md). Asserted: the volumetric locking the thesis
  // reports -- the error against Lame grows as nu -> 0.5 -- and the fully integrated plain C3D8
  // (= CalculiX C3D8 to 0.01 %) locks worse than C3D14 at every nu.
  double previous = 0.0;
  for (const char* name : {"7-nu0.49", "7-nu0.499", "7-nu0.4999"}) {
    const double error = relative_error(ours(name, "C3D14"), bench(name).theory);
    EXPECT_GT(error, previous) << name;
    previous = error;
    EXPECT_LT(ours(name, "C3D8"), ours(name, "C3D14")) << name;
  }
  const double c3d8 = ours("7-nu0.49", "C3D8");
  EXPECT_NEAR(c3d8, calculix("7-nu0.49", "C3D8"), 1e-4 * c3d8);
}

TEST_F(Spec3_1, PatchTestEveryFamily) {
  // SPEC §3.1.8: sigma = 2000, tau = 400 at every integration point for C3D14 alone, C3D21 +
  // C3D20, C3D28 + C3D20, C3D8 and C3D20 (Tab 3.13 "8 patch A A A A A"): worst component within
  // 1e-6 relative.
  for (const char* family : kElementFamilies)
    EXPECT_NEAR(ours("8-patch", family), 2000.0, 2000.0 * 1e-6) << family;
}

TEST_F(Spec3_1, PlainC3D8MatchesCalculiX) {
  // SPEC §3.1.1-§3.1.3: Styk's C3D8 is the plain 2x2x2 brick like CalculiX's (the thesis' Abaqus
  // C3D8 integrates the volumetric part selectively; docs/verification.md §3.1.1), so it is
  // asserted against CalculiX 2.20 on the identical deck: tolerance 0.01 %.
  for (const char* name : {"1a-n6", "1a-n24", "1b-n12", "1b-n24", "2a-regular", "2a-distorted",
                           "2b-regular", "2b-distorted", "3a", "3b"}) {
    const double c3d8 = ours(name, "C3D8");
    EXPECT_NEAR(c3d8, calculix(name, "C3D8"), 1e-4 * std::abs(c3d8)) << name;
  }
}

TEST_F(Spec3_1, GradeTable313) {
  // SPEC §3.1.9: the table has the 13 rows of Tab 3.13, five element columns, each cell
  // "ours / thesis"; grades follow Tab 3.12 (A < 2 %, B < 10 %, C < 20 %, D < 50 %, E).
  EXPECT_EQ(grade(1.019, 1.0), 'A');
  EXPECT_EQ(grade(0.95, 1.0), 'B');
  EXPECT_EQ(grade(1.15, 1.0), 'C');
  EXPECT_EQ(grade(0.6, 1.0), 'D');
  EXPECT_EQ(grade(0.4, 1.0), 'E');
  std::vector<BenchmarkCase> graded;
  for (const BenchmarkCase& c : cases_)
    if (!c.grade_row.empty()) graded.push_back(c);
  ASSERT_EQ(graded.size(), 13u);
  const std::vector<CaseOutcome> outcomes = run_cases(graded, full_->registry);
  const std::string table = grade_table_markdown(outcomes);
  std::printf("%s", table_313_section(outcomes).c_str());
  int rows = 0;
  for (std::size_t at = table.find("\n| "); at != std::string::npos;
       at = table.find("\n| ", at + 1))
    ++rows;
  EXPECT_EQ(rows, 13);
  EXPECT_EQ(table.find("n/a"), std::string::npos);
  for (const CaseOutcome& o : outcomes) {
    EXPECT_NE(table.find("| " + o.bench.grade_row), std::string::npos) << o.bench.grade_row;
    for (int f = 0; f < kFamilyCount; ++f) {
      ASSERT_TRUE(o.ours[f].value) << o.bench.name << " " << o.ours[f].failure;
    }
  }
  // The patch-test row is A for every family (SPEC §3.1.8).
  EXPECT_NE(table.find("| 8 patch | A / A | A / A | A / A | A / A | A / A |"), std::string::npos);
}

TEST_F(Spec3_1, MarkedSectionOfTheVerificationPage) {
  // `styk verify --table 3.13 --write FILE` replaces the text between the markers only.
  const std::string text =
      std::string("intro\n") + kTable313Begin + "\nold\n" + kTable313End + "\noutro\n";
  EXPECT_EQ(replace_marked_section(text, kTable313Begin, kTable313End, "new"),
            std::string("intro\n") + kTable313Begin + "\nnew\n" + kTable313End + "\noutro\n");
  EXPECT_THROW(replace_marked_section("no markers", kTable313Begin, kTable313End, "x"),
               std::runtime_error);
  std::ifstream page(std::string(STYK_SOURCE_DIR) + "/docs/verification.md");
  const std::string doc((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_NO_THROW(replace_marked_section(doc, kTable313Begin, kTable313End, "x"));
}

}  // namespace
}  // namespace styk::verify
