// The shells' transverse shear forces Q13, Q23 (Abaqus' SF4, SF5 of a shell) in the results
// (IncrementResult::SFQ), the HDF5 file (dataset SFQ), the .dat report (the block after SF) and
// VTU (cell array SFQ): docs/results.md. The cantilever plate strip of shell_decks.hpp (width
// b = 0.2, clamped at x = 0) under a uniform edge shear P = 2: statics gives Q13 = P / b = 10
// and Q23 = 0 at every section. Asserted for S4, S8R, S9R at every station to 1e-6 relative;
// STRI3's shear force comes from its moments' equilibrium, a coarse estimate documented in
// docs/elements.md (mean Q13 9.4624, -5.4 %), asserted as its mean to 1e-3 of that value.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "shell_decks.hpp"
#include "styk/io/dat_writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/vtu_export.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

constexpr double kP = 2.0, kQ = kP / 0.2;

struct Solved {
  Model model;
  Results results;
};

Solved solve_strip(const std::string& type, const ElementRegistry& registry) {
  const test::ShellGrid g = test::cantilever_strip(type, kP, 4, "*EL PRINT, ELSET=SHELL\nSF\n");
  Solved out{
      test::read_shell_deck("shear_output_" + type + ".inp", test::shell_grid_deck(g), registry),
      {}};
  out.results = run_static_analysis(out.model, registry, SolveOptions{}, nullptr, nullptr);
  return out;
}

TEST(ShellShearOutput, SfqHoldsTheEdgeShearAtEveryStation) {
  const ElementRegistry registry = test::builtin_registry();
  for (const char* type : {"S4", "S8R", "S9R", "STRI3"}) {
    const Solved s = solve_strip(type, registry);
    const IncrementResult& inc = s.results.increments.back();
    ASSERT_EQ(inc.SFQ.size(), static_cast<std::size_t>(inc.station_offset.back())) << type;
    double q13_sum = 0.0;
    for (const auto& q : inc.SFQ) {
      q13_sum += q[0];
      if (std::string(type) == "STRI3") continue;
      EXPECT_NEAR(q[0], kQ, 1e-6 * kQ) << type;
      EXPECT_NEAR(q[1], 0.0, 1e-6 * kQ) << type;
    }
    if (std::string(type) == "STRI3") {
      EXPECT_NEAR(q13_sum / inc.SFQ.size(), 9.46242, 1e-3 * 9.46242);
    }
  }
}

TEST(ShellShearOutput, HdfDatAndVtuCarrySfq) {
  const ElementRegistry registry = test::builtin_registry();
  const std::filesystem::path dir = test::test_scratch_dir("tests/shell_shear_output");
  const Solved s = solve_strip("S8R", registry);
  const IncrementResult& inc = s.results.increments.back();
  const int stations = inc.station_offset.back();
  ASSERT_EQ(stations, 8 * 4);  // 8 elements, 2x2 stations each

  // HDF5: the dataset SFQ (stations x 2) reads back bit for bit.
  const std::string h5 = (dir / "strip.styk.h5").string();
  write_results_file(h5, s.model, s.results);
  const ResultsFileContents back = read_results_file(h5);
  ASSERT_EQ(back.results.increments.back().SFQ, inc.SFQ);

  // .dat: after the SF block, "transverse shear forces" with one row per station: id, station,
  // Q13, Q23.
  std::ostringstream dat;
  write_dat(dat, s.model, s.results);
  const std::string text = dat.str();
  const std::size_t block = text.find(" transverse shear forces (elem, integ.pnt.,sf4,sf5)");
  ASSERT_NE(block, std::string::npos) << text;
  ASSERT_LT(text.find(" section forces (elem, integ.pnt.,sf1,sf2,sf3)"), block);
  std::istringstream rows(text.substr(block));
  std::string line;
  std::getline(rows, line);  // the header
  int read = 0;
  while (std::getline(rows, line)) {
    std::istringstream row(line);
    int id = 0, station = 0;
    double q13 = 0.0, q23 = 0.0;
    if (!(row >> id >> station >> q13 >> q23)) continue;  // the blank line after the header
    EXPECT_NEAR(q13, kQ, 1e-6 * kQ) << line;
    EXPECT_NEAR(q23, 0.0, 1e-6 * kQ) << line;
    ++read;
  }
  EXPECT_EQ(read, stations);

  // VTU: the cell array SFQ with two components (the element's mean).
  const std::string vtu = (dir / "strip.vtu").string();
  write_vtu(vtu, s.model, registry, &inc);
  std::ifstream in(vtu);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t array = xml.find("Name=\"SFQ\"");
  ASSERT_NE(array, std::string::npos);
  EXPECT_NE(xml.substr(array, 120).find("NumberOfComponents=\"2\""), std::string::npos)
      << xml.substr(array, 120);
}

}  // namespace
}  // namespace styk
