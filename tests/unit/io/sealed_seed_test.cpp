// tests/inputs/results/sealed-cube.styk.h5, the seed of the results-file fuzzing harness
// (docs/fuzzing.md: the short run of the test command is seeded with sealed files only): it must
// stay a whole, sealed file of the current schema, or the harness would mutate a file the reader
// refuses for another reason. tests/inputs/results/cube.inp solved by `styk solve`: 8 nodes, one
// C3D8, two steps of one increment each.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"

namespace styk {
namespace {

const std::string kSeed =
    std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/sealed-cube.styk.h5";

TEST(SealedSeed, IsWholeSealedAndCurrent) {
  const std::optional<io::ResultsSeal> seal = io::verify_results_seal(kSeed);
  ASSERT_TRUE(seal.has_value()) << kSeed << " is not sealed";
  const ResultsFileContents contents = read_results_file(kSeed);
  EXPECT_TRUE(contents.verified);
  EXPECT_TRUE(contents.sealed);
  EXPECT_EQ(contents.schema_version, 1);
  EXPECT_EQ(contents.model.node_count(), 8);
  EXPECT_EQ(contents.model.element_count(), 1);
  EXPECT_EQ(contents.results.increments.size(), 2u);
}

}  // namespace
}  // namespace styk
