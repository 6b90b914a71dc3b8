// libFuzzer harness of the results-file reader (read_results_file: what styk render, export and
// check open; docs/results.md "Integrity"). The bytes are written to a file and read: accepted
// outcomes are the contents, or InputError (a damaged or foreign file, named); anything else —
// another exception, a crash, a sanitizer report — is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "fuzz_scratch.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = styk::fuzz::scratch_path("results.styk.h5");
  styk::fuzz::write_bytes(path, data, size);
  try {
    (void)styk::read_results_file(path);
  } catch (const styk::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: read_results_file threw %s\n", e.what());
    std::abort();
  }
  return 0;
}
