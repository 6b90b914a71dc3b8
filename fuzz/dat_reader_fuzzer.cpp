// libFuzzer harness of the .dat reader (parse_dat_blocks, parse_dat_displacements; the ccx
// cross-checks read CalculiX's reports with it). Accepted: blocks, or the std::runtime_error the
// reader documents (naming the line); anything else (a logic_error such as out_of_range, a
// crash, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>

#include "styk/io/dat_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream blocks(text);
    (void)styk::parse_dat_blocks(blocks);
    std::istringstream displacements(text);
    (void)styk::parse_dat_displacements(displacements);
  } catch (const std::runtime_error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: the .dat reader threw %s\n", e.what());
    std::abort();
  }
  return 0;
}
