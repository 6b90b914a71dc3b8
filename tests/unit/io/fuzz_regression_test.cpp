// Inputs the fuzzers found (docs/fuzzing.md), kept as regression cases in tests/inputs/fuzz/:
// every results file there must be refused as damaged by name (InputError, "the file is
// damaged"), never crash or stop the process; every .dat must be read or refused with the
// reader's std::runtime_error naming its line.
//   results-huge-metadata-allocation.styk.h5: a flipped size in the HDF5 metadata makes the
//   library ask malloc for an impossible buffer; it must come back as a damaged file.
//   results-compact-layout-without-data.styk.h5: /model/elements/types turned into a compact
//   dataset without data; HDF5 copied from a NULL buffer (SIGSEGV) until the reader checked it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "styk/core/diagnostics.hpp"
#include "styk/io/dat_reader.hpp"
#include "styk/io/results_file.hpp"

namespace styk {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryFoundInputIsRefusedByName) {
  const fs::path dir = fs::path(STYK_SOURCE_DIR) / "tests" / "inputs" / "fuzz";
  int results_files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string path = entry.path().string();
    if (path.size() > 8 && path.compare(path.size() - 8, 8, ".styk.h5") == 0) {
      ++results_files;
      try {
        (void)read_results_file(path);
        ADD_FAILURE() << path << " was read";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
      }
    } else if (entry.path().extension() == ".dat") {
      std::ifstream in(path);
      try {
        (void)parse_dat_blocks(in);
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(".dat line"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GE(results_files, 1);
}

}  // namespace
}  // namespace styk
