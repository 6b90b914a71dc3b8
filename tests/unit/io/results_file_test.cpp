// Round trip and failure behaviour of the .styk.h5 results file (docs/results.md).
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>

#include "io_test_support.hpp"
#include "styk/io/results_file.hpp"

namespace styk {
namespace {

// Two elements of different types (one Styk cannot draw, to show any type name is stored), sets
// whose names need escaping, and three increments over two steps given out of order.
Model small_model() {
  Model model = io_test::unit_cube();
  model.source = "/decks/cube.inp";
  model.heading = "round trip";
  model.add_node(42, {2.0, 0.5, -0.25}, {});
  model.add_element(9, "C3D28", {1, 8, 2}, {});
  model.nsets["A/B%C"] = NodeSet{"A/B%C", {1, 8}, {}};
  model.elsets["."] = ElementSet{".", {1}, {}};
  return model;
}

IncrementResult increment(int step, int number, double total_time, const Model& model) {
  IncrementResult inc;
  inc.step = step;
  inc.increment = number;
  inc.step_time = 0.25 * number;
  inc.total_time = total_time;
  for (int n = 0; n < model.node_count(); ++n) {
    inc.U.push_back({0.001 * n, -0.5 * n * total_time, 1e-300 * n});
    inc.RF.push_back({n == 0 ? -3.5 : 0.0, 0.0, 7.0 * step});
  }
  inc.ip_offset = {0, 8, 11};
  for (int p = 0; p < 11; ++p) {
    inc.S.push_back({1.0 * p, 2.0, 3.0, 4.0, 5.0, 6.0 * total_time});
    inc.E.push_back({1e-3 * p, 0.0, 0.0, 0.0, -1e-4, 2e-5});
  }
  return inc;
}

void expect_same(const IncrementResult& a, const IncrementResult& b) {
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.increment, b.increment);
  EXPECT_EQ(a.step_time, b.step_time);
  EXPECT_EQ(a.total_time, b.total_time);
  EXPECT_EQ(a.U, b.U);
  EXPECT_EQ(a.RF, b.RF);
  EXPECT_EQ(a.ip_offset, b.ip_offset);
  EXPECT_EQ(a.S, b.S);
  EXPECT_EQ(a.E, b.E);
}

TEST(ResultsFile, RoundTripsMeshSetsAndIncrementsExactly) {
  const Model model = small_model();
  Results results;
  // Step 10 before step 2 in the name order of the groups: reading must restore numeric order.
  results.increments = {increment(2, 1, 1.25, model), increment(10, 3, 9.0, model),
                        increment(2, 2, 1.5, model)};
  const std::string path = io_test::fresh_dir("roundtrip") + "/r.styk.h5";
  write_results_file(path, model, results);
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));

  const ResultsFileContents read = read_results_file(path);
  EXPECT_EQ(read.schema_version, 1);
  EXPECT_FALSE(read.styk_version.empty());
  EXPECT_EQ(read.model.source, model.source);
  EXPECT_EQ(read.model.heading, model.heading);
  EXPECT_EQ(read.model.node_ids, model.node_ids);
  EXPECT_EQ(read.model.coords, model.coords);
  EXPECT_EQ(read.model.connectivity, model.connectivity);
  ASSERT_EQ(read.model.element_count(), 2);
  for (int e = 0; e < 2; ++e) {
    EXPECT_EQ(read.model.elements[e].id, model.elements[e].id);
    EXPECT_EQ(read.model.elements[e].type, model.elements[e].type);
    EXPECT_EQ(read.model.elements[e].node_count, model.elements[e].node_count);
  }
  EXPECT_EQ(read.model.node_index(42), 8);
  EXPECT_EQ(read.model.element_index(9), 1);
  ASSERT_EQ(read.model.nsets.size(), model.nsets.size());
  for (const auto& [name, set] : model.nsets) EXPECT_EQ(read.model.nsets.at(name).nodes, set.nodes);
  ASSERT_EQ(read.model.elsets.size(), model.elsets.size());
  for (const auto& [name, set] : model.elsets)
    EXPECT_EQ(read.model.elsets.at(name).elements, set.elements);

  ASSERT_EQ(read.results.increments.size(), 3u);
  expect_same(read.results.increments[0], results.increments[0]);
  expect_same(read.results.increments[1], results.increments[2]);
  expect_same(read.results.increments[2], results.increments[1]);
}

TEST(ResultsFile, IncrementWithoutIntegrationPointDataRoundTrips) {
  const Model model = io_test::unit_cube();
  Results results;
  results.increments.push_back(increment(1, 1, 1.0, model));
  results.increments[0].ip_offset.clear();
  results.increments[0].S.clear();
  results.increments[0].E.clear();
  results.increments[0].RF.clear();
  const std::string path = io_test::fresh_dir("no_ip") + "/r.styk.h5";
  write_results_file(path, model, results);
  const ResultsFileContents read = read_results_file(path);
  ASSERT_EQ(read.results.increments.size(), 1u);
  expect_same(read.results.increments[0], results.increments[0]);
}

// The optional element results (*EL PRINT/FILE ENER, THE, EVOL, ELSE, ERR) round-trip exactly
// when present; an increment without them reads back with the vectors empty, and a vector of
// the wrong length is refused.
TEST(ResultsFile, OptionalElementResultsRoundTrip) {
  const Model model = small_model();
  Results results;
  results.increments = {increment(1, 1, 1.0, model), increment(2, 1, 2.0, model)};
  IncrementResult& full = results.increments[0];
  for (int p = 0; p < 11; ++p) {
    full.ENER.push_back(0.5 * p);
    full.THE.push_back({1e-5 * p, 2e-5, 3e-5, 0.0, 0.0, -1e-6});
  }
  full.element_volume = {1.0, 0.125};
  full.element_energy = {3.5, 0.0};
  full.ERR = {12.5, 0.75};
  const std::string path = io_test::fresh_dir("extras") + "/r.styk.h5";
  write_results_file(path, model, results);
  const ResultsFileContents read = read_results_file(path);
  ASSERT_EQ(read.results.increments.size(), 2u);
  const IncrementResult& back = read.results.increments[0];
  EXPECT_EQ(back.ENER, full.ENER);
  EXPECT_EQ(back.THE, full.THE);
  EXPECT_EQ(back.element_volume, full.element_volume);
  EXPECT_EQ(back.element_energy, full.element_energy);
  EXPECT_EQ(back.ERR, full.ERR);
  const IncrementResult& bare = read.results.increments[1];
  EXPECT_TRUE(bare.ENER.empty() && bare.THE.empty() && bare.element_volume.empty() &&
              bare.element_energy.empty() && bare.ERR.empty());

  // One ERR value for two elements: refused before the file is touched.
  full.ERR = {12.5};
  const std::string bad = io_test::fresh_dir("extras_bad") + "/r.styk.h5";
  try {
    write_results_file(bad, model, results);
    ADD_FAILURE() << "an ERR vector of the wrong length was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ERR has 1 rows, expected 2"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(io_test::file_exists(bad));
}

TEST(ResultsFile, MismatchedResultsThrowAndLeaveExistingFileUntouched) {
  const Model model = io_test::unit_cube();
  const std::string path = io_test::fresh_dir("mismatch") + "/r.styk.h5";
  { std::ofstream(path) << "previous contents"; }
  Results results;
  results.increments.push_back(increment(1, 1, 1.0, model));
  results.increments[0].U.pop_back();  // 7 displacements for 8 nodes
  try {
    write_results_file(path, model, results);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("7 displacements for 8 nodes"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(io_test::read_text(path), "previous contents");
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));
}

TEST(ResultsFile, DuplicateIncrementThrowsAndLeavesNoFile) {
  const Model model = io_test::unit_cube();
  const std::string path = io_test::fresh_dir("duplicate") + "/r.styk.h5";
  Results results;
  results.increments = {increment(1, 1, 1.0, model), increment(1, 1, 1.0, model)};
  EXPECT_THROW(write_results_file(path, model, results), std::runtime_error);
  EXPECT_FALSE(io_test::file_exists(path));
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));
}

TEST(ResultsFile, UnwritableDirectoryGivesClearError) {
  const std::string path = io_test::fresh_dir("unwritable") + "/no/such/dir/r.styk.h5";
  try {
    write_results_file(path, io_test::unit_cube(), Results{});
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write results file " + path), std::string::npos)
        << e.what();
  }
}

TEST(ResultsFile, ReadingAMissingOrForeignFileGivesClearError) {
  const std::string dir = io_test::fresh_dir("foreign");
  try {
    read_results_file(dir + "/missing.styk.h5");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/missing.styk.h5"), std::string::npos);
  }
  { std::ofstream(dir + "/text.styk.h5") << "not hdf5 at all"; }
  EXPECT_THROW(read_results_file(dir + "/text.styk.h5"), std::runtime_error);
}

// A million-node model round trips (the arrays cross HDF5's chunk size many times over). How long
// it takes, with and without checksums, is measured in bench/io, not asserted here.
TEST(ResultsFile, MillionNodeModelRoundTrips) {
  constexpr int kSide = 100;  // 100^3 = 1,000,000 nodes
  Model model;
  model.node_ids.reserve(kSide * kSide * kSide);
  model.coords.reserve(kSide * kSide * kSide);
  auto node = [&](int i, int j, int k) { return (k * kSide + j) * kSide + i; };
  for (int k = 0; k < kSide; ++k)
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i)
        model.add_node(node(i, j, k) + 1, {1.0 * i, 1.0 * j, 1.0 * k}, {});
  // Every other cell: about 120,000 C3D8 elements, 8 integration points each.
  for (int k = 0; k + 1 < kSide; k += 2)
    for (int j = 0; j + 1 < kSide; j += 2)
      for (int i = 0; i + 1 < kSide; i += 2)
        model.add_element(model.element_count() + 1, "C3D8",
                          {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                           node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                           node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)},
                          {});
  IncrementResult inc;
  inc.U.assign(model.node_count(), Vec3{1.0, 2.0, 3.0});
  inc.RF.assign(model.node_count(), Vec3{0.0, 0.0, 0.5});
  for (int e = 0; e <= model.element_count(); ++e) inc.ip_offset.push_back(8 * e);
  inc.S.assign(inc.ip_offset.back(), Tensor6{1, 2, 3, 4, 5, 6});
  inc.E.assign(inc.ip_offset.back(), Tensor6{1e-3, 0, 0, 0, 0, 0});
  inc.U.back() = {-1.0, -2.0, -3.0};
  Results results;
  results.increments.push_back(inc);

  const std::string path = io_test::fresh_dir("million") + "/big.styk.h5";
  write_results_file(path, model, results);
  const ResultsFileContents read = read_results_file(path);
  EXPECT_TRUE(read.verified);
  ASSERT_EQ(read.model.node_count(), 1000000);
  EXPECT_EQ(read.model.coords.back(), (Vec3{99.0, 99.0, 99.0}));
  EXPECT_EQ(read.model.connectivity, model.connectivity);
  ASSERT_EQ(read.results.increments.size(), 1u);
  EXPECT_EQ(read.results.increments[0].U.back(), (Vec3{-1.0, -2.0, -3.0}));
  EXPECT_EQ(read.results.increments[0].S.size(), inc.S.size());
}

}  // namespace
}  // namespace styk
