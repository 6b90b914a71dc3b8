// The recovered fields in the results file (docs/results.md): written and read back bit for bit,
// absent fields stay absent, wrong sizes are refused before anything is written.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "hex_model_builder.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/io/results_file.hpp"

namespace styk {
namespace {

std::string scratch_file(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(STYK_BINARY_DIR) / "tests" / "unit" / "recovery" / "scratch";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::filesystem::remove(path);
  return path.string();
}

std::vector<Tensor6> numbered(std::size_t rows, double base) {
  std::vector<Tensor6> out(rows);
  for (std::size_t i = 0; i < rows; ++i)
    for (int k = 0; k < 6; ++k) out[i][k] = base + 6.0 * i + k + 1.0 / 3.0;
  return out;
}

class RecoveredFieldsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_elements(registry_);
    test::HexModelBuilder builder(registry_, 1000.0, 0.3);
    builder.add(
        "C3D8",
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}});
    builder.add(
        "C3D20",
        {{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}}});
    model_ = builder.finish();
  }

  IncrementResult full_increment() const {
    IncrementResult inc;
    const std::size_t nodes = model_.coords.size(), slots = model_.connectivity.size();
    inc.U.assign(nodes, Vec3{1.0, 2.0, 3.0});
    inc.RF.assign(nodes, Vec3{0.0, 0.0, 0.0});
    inc.ip_offset = {0, 8, 35};
    inc.S = numbered(35, 0.0);
    inc.E = numbered(35, -1e-3);
    inc.S_element_nodes = numbered(slots, 1e3);
    inc.E_element_nodes = numbered(slots, 2e3);
    inc.S_centroid = numbered(2, 3e3);
    inc.E_centroid = numbered(2, 4e3);
    inc.S_nodal_I = numbered(nodes, 5e3);
    inc.S_nodal_II = numbered(nodes, 6e3);
    inc.E_nodal_I = numbered(nodes, 7e3);
    inc.E_nodal_II = numbered(nodes, 8e3);
    return inc;
  }

  ElementRegistry registry_;
  Model model_;
};

TEST_F(RecoveredFieldsFile, RoundTripIsExact) {
  Results results;
  results.increments.push_back(full_increment());
  IncrementResult second;  // a later increment without recovered values
  second.step = 2;
  results.increments.push_back(second);
  const std::string path = scratch_file("round_trip.styk.h5");
  write_results_file(path, model_, results);
  const ResultsFileContents read = read_results_file(path);
  ASSERT_EQ(read.results.increments.size(), 2u);
  const IncrementResult& a = results.increments[0];
  const IncrementResult& b = read.results.increments[0];
  EXPECT_EQ(b.S_element_nodes, a.S_element_nodes);
  EXPECT_EQ(b.E_element_nodes, a.E_element_nodes);
  EXPECT_EQ(b.S_centroid, a.S_centroid);
  EXPECT_EQ(b.E_centroid, a.E_centroid);
  EXPECT_EQ(b.S_nodal_I, a.S_nodal_I);
  EXPECT_EQ(b.S_nodal_II, a.S_nodal_II);
  EXPECT_EQ(b.E_nodal_I, a.E_nodal_I);
  EXPECT_EQ(b.E_nodal_II, a.E_nodal_II);
  EXPECT_EQ(b.S, a.S);
  const IncrementResult& empty = read.results.increments[1];
  EXPECT_TRUE(empty.S_element_nodes.empty());
  EXPECT_TRUE(empty.S_centroid.empty());
  EXPECT_TRUE(empty.S_nodal_I.empty());
  EXPECT_TRUE(empty.E_nodal_II.empty());
}

TEST_F(RecoveredFieldsFile, WrongSizesAreRefusedBeforeWriting) {
  const std::string path = scratch_file("wrong.styk.h5");
  for (int which = 0; which < 3; ++which) {
    Results results;
    results.increments.push_back(full_increment());
    IncrementResult& inc = results.increments[0];
    std::string field;
    if (which == 0) inc.S_element_nodes.pop_back(), field = "S_element_nodes";
    if (which == 1) inc.E_centroid.push_back({}), field = "E_centroid";
    if (which == 2) inc.S_nodal_II.resize(3), field = "S_nodal_II";
    try {
      write_results_file(path, model_, results);
      ADD_FAILURE() << field << ": no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
  }
}

}  // namespace
}  // namespace styk
