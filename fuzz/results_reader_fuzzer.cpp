// libFuzzer harness of the results-file reader (read_results_file: what styk render, export and
// check open; docs/results.md "Integrity"). The bytes are written to a file and read: accepted
// outcomes are the contents, or InputError (a damaged or foreign file, named); anything else —
// another exception, a crash, a sanitizer report — is a finding.
//
// With STYK_FUZZ_RESEAL=1 in the environment, a mutated input whose HDF5 superblock still sits
// behind the 512-byte user block is sealed again before it is read, so the mutation reaches HDF5's
// parsing behind the seal instead of being refused by it (what a file damaged before it was
// sealed, or an unsealed file, would do). docs/fuzzing.md gives what that finds inside HDF5.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#include "fuzz_scratch.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"

namespace {

bool reseal_requested() {
  static const bool requested = [] {
    const char* value = std::getenv("STYK_FUZZ_RESEAL");
    return value != nullptr && std::string(value) == "1";
  }();
  return requested;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = styk::fuzz::scratch_path("results.styk.h5");
  styk::fuzz::write_bytes(path, data, size);
  if (reseal_requested()) {
    try {
      styk::io::seal_results_file(path);
    } catch (const std::runtime_error&) {
      // No superblock behind a user block: the input is read as it is.
    }
  }
  try {
    (void)styk::read_results_file(path);
  } catch (const styk::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: read_results_file threw %s\n", e.what());
    std::abort();
  }
  return 0;
}
