// SPEC §3.1 element tests (MacNeal-Harder style) for the tetrahedra C3D4/C3D10 and the wedges
// C3D6/C3D15: the same builders and measures as `styk verify` (studies/verify), the bricks split
// by mesher/split.hpp (6 tetrahedra or 2 wedges per brick). Asserted per case and family:
// - our value equals CalculiX 2.20 on the identical deck (written by write_inp, solved by `ccx`)
//   to 1e-6 relative: same shape functions, integration points and consistent loads;
// - the value itself, as measured with Styk and ccx 2.20 (the table below), to 1e-4 relative,
//   with its grade against the theory of SPEC Tab 3.12 (A < 2 %, ..., E > 50 %).
// §3.1.8 patch test: sigma = 2000, tau = 400 at every integration point to 1e-9 relative.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/studies/verify/report.hpp"
#include "support/ccx_runner.hpp"
#include "support/plugin_registry_suite.hpp"

namespace styk::verify {
namespace {

class Spec3_1Solids : public test::PluginRegistrySuite<> {
 protected:
  static const BenchmarkCase& bench(const std::string& name) {
    static const std::vector<BenchmarkCase> cases = benchmark_cases();
    const BenchmarkCase* c = find_case(cases, name);
    if (!c) throw std::invalid_argument("no case " + name);
    return *c;
  }

  // Ours and CalculiX's value of case `name` meshed with `family`.
  static std::pair<double, double> ours_and_ccx(const std::string& name,
                                                const std::string& family) {
    const BenchmarkCase& c = bench(name);
    const Model model = build_case_model(c, family, registry());
    const double ours = run_case(c, family, registry());
    const std::filesystem::path dir = std::filesystem::path(STYK_BINARY_DIR) / "tests" /
                                      "verification" / "ccx_solids" / (name + "_" + family);
    std::filesystem::create_directories(dir);
    {
      std::ofstream deck(dir / "job.inp");
      write_inp(model, deck);
    }
    if (test::run_ccx(dir, "job").exit_code != 0)
      throw std::runtime_error("ccx failed in " + dir.string());
    std::ifstream dat(dir / "job.dat");
    const std::vector<DatDisplacements> blocks = parse_dat_displacements(dat);
    if (blocks.empty()) throw std::runtime_error("no displacements in " + dir.string());
    std::vector<Vec3> U(model.node_count(), Vec3{0, 0, 0});
    for (const auto& [id, u] : blocks.back().u) U.at(model.node_index(id)) = u;
    return {ours, measure_displacements(c, model, U)};
  }
};

struct Expected {
  const char* name;  // case of studies/verify
  const char* family;
  double value;  // measured (docs/verification.md)
  char grade;    // against the case's theory
};

// SPEC §3.1.1 (L = 6 cantilever: 1a tension theory 3.0e-5, 1b bending 0.108) and §3.1.2 (10 x 2 x
// 2 beam, SPEC's distorted stand-in mesh: 2a 1.6667e-3, 2b 0.1).
const Expected kExpected[] = {
    {"1a-n6", "C3D4", 2.934969e-05, 'B'},        {"1a-n6", "C3D10", 2.979356e-05, 'A'},
    {"1a-n6", "C3D6", 2.956718e-05, 'A'},        {"1a-n6", "C3D15", 2.984714e-05, 'A'},
    {"1b-n6", "C3D4", 3.402521e-03, 'E'},        {"1b-n6", "C3D10", 1.039810e-01, 'B'},
    {"1b-n6", "C3D6", 2.618914e-02, 'E'},        {"1b-n6", "C3D15", 1.048535e-01, 'B'},
    {"1b-n24", "C3D4", 1.951084e-02, 'E'},       {"1b-n24", "C3D10", 1.071437e-01, 'A'},
    {"1b-n24", "C3D6", 8.542411e-02, 'D'},       {"1b-n24", "C3D15", 1.073275e-01, 'A'},
    {"2a-distorted", "C3D4", 1.635983e-03, 'A'}, {"2a-distorted", "C3D10", 1.651593e-03, 'A'},
    {"2a-distorted", "C3D6", 1.642667e-03, 'A'}, {"2a-distorted", "C3D15", 1.652283e-03, 'A'},
    {"2b-distorted", "C3D4", 3.131854e-02, 'E'}, {"2b-distorted", "C3D10", 9.499515e-02, 'B'},
    {"2b-distorted", "C3D6", 6.255424e-02, 'D'}, {"2b-distorted", "C3D15", 9.913414e-02, 'A'},
};

TEST_F(Spec3_1Solids, MacNealHarderEntriesMatchCalculixAndTheirGrades) {
  for (const Expected& e : kExpected) {
    const auto [ours, ccx] = ours_and_ccx(e.name, e.family);
    const double theory = bench(e.name).theory;
    std::printf("%-14s %-6s ours %.6e  ccx %.6e  theory %.5g  ratio %.4f  grade %c\n", e.name,
                e.family, ours, ccx, theory, ours / theory, grade(ours, theory));
    EXPECT_NEAR(ours, ccx, 1e-6 * std::abs(ccx)) << e.name << " " << e.family;
    EXPECT_NEAR(ours, e.value, 1e-4 * std::abs(e.value)) << e.name << " " << e.family;
    EXPECT_EQ(grade(ours, theory), e.grade) << e.name << " " << e.family;
  }
}

// SPEC §3.1.8 on the 7-brick MacNeal-Harder cube split into straight-sided tetrahedra: the
// boundary displacements of constant strain 1e-3 give sigma = 2000 and tau = 400 at every
// integration point (reported as the worst point on the sigma scale), to 1e-9 relative. Wedges
// cannot be split conformingly from these 7 bricks (their axes differ): the builder refuses them
// by name rather than build a cracked patch.
TEST_F(Spec3_1Solids, PatchTestOnTheSplitCube) {
  for (const char* family : {"C3D4", "C3D10"}) {
    const double worst = run_case(bench("8-patch"), family, registry());
    EXPECT_NEAR(worst, 2000.0, 1e-9 * 2000.0) << family;
  }
  for (const char* family : {"C3D6", "C3D15"}) {
    try {
      run_case(bench("8-patch"), family, registry());
      ADD_FAILURE() << family << " patch built";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("wedges cannot be split conformingly"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace styk::verify
