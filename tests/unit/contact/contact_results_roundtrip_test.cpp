// Contact results through the results file (docs/results.md, group "contact"): a real frictional
// contact solve written with write_results_file and read back with read_results_file gives every
// contact dataset of every increment bit for bit (status, area, pressure, the two shears, the slip
// vector, gap, frame, force; per pair the total force and moment; the equilibrium rows and
// residual). One consumer on top: `styk export --vtu` of that file writes the contact point arrays
// (CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS) of the in-memory results, byte for byte.
//
// Deck tests/inputs/contact/contact_results_roundtrip.inp: a 3 x 3 C3D8 block [0,2]x[0,1]x[1,1.5]
// on a 4 x 2 one [0,2]x[0,1]x[0,1] (non-matching: node-to-surface), mu = 0.3, the lower base
// clamped, the upper held by contact alone. Step 1: pressure 1 on the top. Step 2 (two fixed
// increments): a lift of 4 x 0.15 at the top edge x = 0 and a push of 16 x 0.015 in x.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "base64.hpp"
#include "cli_runner.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/results_file.hpp"
#include "styk/solver/analysis.hpp"
#include "support/element_registries.hpp"

namespace styk::testing {
namespace {

const std::string kDeck =
    std::string(STYK_SOURCE_DIR) + "/tests/inputs/contact/contact_results_roundtrip.inp";

// Solved once for the suite: the model, its results and the file they were written to.
class ContactResultsRoundTrip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ElementRegistry registry = test::builtin_registry();
    model_ = std::make_unique<Model>(read_inp(kDeck, registry));
    results_ = std::make_unique<Results>(
        run_static_analysis(*model_, registry, SolveOptions{}, nullptr, nullptr));
    // ctest runs the cases of this suite in parallel processes: one directory each.
    dir_ = scratch_dir("contact_results_roundtrip_" + std::to_string(getpid()));
    path_ = dir_ + "/pair.styk.h5";
    write_results_file(path_, *model_, *results_);
  }
  static void TearDownTestSuite() {
    model_.reset();
    results_.reset();
    std::filesystem::remove_all(dir_);
  }
  static std::unique_ptr<Model> model_;
  static std::unique_ptr<Results> results_;
  static std::string dir_, path_;
};
std::unique_ptr<Model> ContactResultsRoundTrip::model_;
std::unique_ptr<Results> ContactResultsRoundTrip::results_;
std::string ContactResultsRoundTrip::dir_;
std::string ContactResultsRoundTrip::path_;

// Bitwise equality of doubles (a == b would also pass -0.0 for 0.0).
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
template <std::size_t N>
bool same(const std::array<double, N>& a, const std::array<double, N>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * N) == 0;
}

// The deck is only a useful round trip if every dataset holds something: several increments,
// stick and slip nodes (and open ones in step 2), shears and slips that are not zero.
TEST_F(ContactResultsRoundTrip, DeckExercisesEveryContactDataset) {
  ASSERT_EQ(results_->increments.size(), 3u);
  int stick = 0, slip = 0, open = 0;
  double largest_shear = 0.0, largest_slip = 0.0;
  for (const IncrementResult& inc : results_->increments) {
    ASSERT_EQ(inc.contact.size(), 16u);  // the 4 x 4 slave nodes
    ASSERT_EQ(inc.contact_pairs.size(), 1u);
    EXPECT_TRUE(inc.contact_equilibrium.valid);
    EXPECT_LT(inc.contact_equilibrium.relative_residual, 1e-8);
    for (const ContactNodeResult& c : inc.contact) {
      stick += c.status == ContactStatus::Stick;
      slip += c.status == ContactStatus::Slip;
      open += c.status == ContactStatus::Open;
      largest_shear = std::max({largest_shear, std::abs(c.shear[0]), std::abs(c.shear[1])});
      largest_slip = std::max({largest_slip, std::abs(c.slip[0]), std::abs(c.slip[1])});
    }
  }
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
  EXPECT_GT(open, 0);
  EXPECT_GT(largest_shear, 1e-3);
  EXPECT_GT(largest_slip, 1e-6);
}

TEST_F(ContactResultsRoundTrip, EveryContactDatasetReadsBackBitForBit) {
  const ResultsFileContents back = read_results_file(path_);
  ASSERT_EQ(back.results.increments.size(), results_->increments.size());
  for (std::size_t k = 0; k < results_->increments.size(); ++k) {
    const IncrementResult& a = results_->increments[k];
    const IncrementResult& b = back.results.increments[k];
    const std::string label =
        "step " + std::to_string(a.step) + " increment " + std::to_string(a.increment);
    EXPECT_EQ(b.step, a.step);
    EXPECT_EQ(b.increment, a.increment);
    EXPECT_TRUE(same(b.step_time, a.step_time)) << label;
    EXPECT_TRUE(same(b.total_time, a.total_time)) << label;
    ASSERT_EQ(b.contact.size(), a.contact.size()) << label;
    for (std::size_t j = 0; j < a.contact.size(); ++j) {
      const ContactNodeResult& x = a.contact[j];
      const ContactNodeResult& y = b.contact[j];
      const std::string row = label + " row " + std::to_string(j);
      EXPECT_EQ(y.node, x.node) << row;
      EXPECT_EQ(y.pair, x.pair) << row;
      EXPECT_EQ(y.status, x.status) << row;
      EXPECT_TRUE(same(y.area, x.area)) << row;
      EXPECT_TRUE(same(y.pressure, x.pressure)) << row;
      EXPECT_TRUE(same(y.shear, x.shear)) << row;
      EXPECT_TRUE(same(y.slip, x.slip)) << row;
      EXPECT_TRUE(same(y.gap, x.gap)) << row;
      EXPECT_TRUE(same(y.normal, x.normal)) << row;
      EXPECT_TRUE(same(y.t1, x.t1)) << row;
      EXPECT_TRUE(same(y.t2, x.t2)) << row;
      EXPECT_TRUE(same(y.force, x.force)) << row;
    }
    ASSERT_EQ(b.contact_pairs.size(), a.contact_pairs.size()) << label;
    for (std::size_t p = 0; p < a.contact_pairs.size(); ++p) {
      EXPECT_TRUE(same(b.contact_pairs[p].force, a.contact_pairs[p].force)) << label;
      EXPECT_TRUE(same(b.contact_pairs[p].moment, a.contact_pairs[p].moment)) << label;
    }
    const ContactEquilibrium& e = a.contact_equilibrium;
    const ContactEquilibrium& f = b.contact_equilibrium;
    EXPECT_EQ(f.valid, e.valid) << label;
    EXPECT_TRUE(same(f.applied, e.applied)) << label;
    EXPECT_TRUE(same(f.reactions, e.reactions)) << label;
    EXPECT_TRUE(same(f.contact_slave, e.contact_slave)) << label;
    EXPECT_TRUE(same(f.contact_master, e.contact_master)) << label;
    EXPECT_TRUE(same(f.relative_residual, e.relative_residual)) << label;
  }
}

// The text of DataArray `name` in a VTU document (the base64 between the tags), "" if absent.
std::string data_array_text(const std::string& vtu, const std::string& name) {
  const std::size_t tag = vtu.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t begin = vtu.find('>', tag) + 1;
  const std::size_t end = vtu.find("</DataArray>", begin);
  const std::string text = vtu.substr(begin, end - begin);
  const std::size_t first = text.find_first_not_of(" \n");
  const std::size_t last = text.find_last_not_of(" \n");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

// What the VTU writer must encode for per-node values: [byte count as UInt64][doubles] in base64.
std::string encoded(const std::vector<double>& values) {
  const std::uint64_t bytes = values.size() * sizeof(double);
  std::string block(sizeof bytes + bytes, '\0');
  std::memcpy(block.data(), &bytes, sizeof bytes);
  std::memcpy(block.data() + sizeof bytes, values.data(), bytes);
  std::string out;
  io::base64_append(block.data(), block.size(), out);
  return out;
}

// `styk export` of increment 2/1 from the file: the contact arrays are those of the in-memory
// increment (docs/results.md "VTU export": NaN where a node is no slave node, magnitudes of shear
// and slip, the status as a number). Every slave node belongs to the one pair.
TEST_F(ContactResultsRoundTrip, ExportWritesTheFilesContactArrays) {
  const std::string dir = scratch_dir("contact_results_export");
  const CommandResult r = run_command(
      styk_executable() + " export '" + path_ + "' --vtu -o out.vtu --step 2 --inc 1", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string vtu = read_file(dir + "/out.vtu");
  const IncrementResult& inc = results_->increments.at(1);
  ASSERT_EQ(inc.step, 2);
  ASSERT_EQ(inc.increment, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = static_cast<std::size_t>(model_->node_count());
  std::vector<double> pressure(n, nan), shear(n, nan), slip(n, nan), gap(n, nan), status(n, nan);
  for (const ContactNodeResult& c : inc.contact) {
    pressure[c.node] = c.pressure;
    shear[c.node] = std::hypot(c.shear[0], c.shear[1]);
    slip[c.node] = std::hypot(c.slip[0], c.slip[1]);
    gap[c.node] = c.gap;
    status[c.node] = static_cast<double>(static_cast<int>(c.status));
  }
  EXPECT_EQ(data_array_text(vtu, "CPRESS"), encoded(pressure));
  EXPECT_EQ(data_array_text(vtu, "CSHEAR"), encoded(shear));
  EXPECT_EQ(data_array_text(vtu, "CSLIP"), encoded(slip));
  EXPECT_EQ(data_array_text(vtu, "CGAP"), encoded(gap));
  EXPECT_EQ(data_array_text(vtu, "CSTATUS"), encoded(status));
}

}  // namespace
}  // namespace styk::testing
