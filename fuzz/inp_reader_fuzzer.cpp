// libFuzzer harness of the .inp reader (read_inp, docs/input.md), *INCLUDE included: the input is
// split at the first line "**FUZZ-INCLUDE" into the deck and the file part.inp beside it, which
// the deck may *INCLUDE (the seeds do). Accepted outcomes: a model, or InputError /
// ResourceLimitError (bad input refused by name, "file:line: message"); anything else — another
// exception, a crash, a sanitizer report, a hang — is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "fuzz_scratch.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"

namespace {

const styk::ElementRegistry& registry() {
  static const styk::ElementRegistry r = [] {
    styk::ElementRegistry out;
    styk::register_builtin_elements(out);
    return out;
  }();
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string marker = "**FUZZ-INCLUDE";
  const std::size_t split = text.find(marker);
  const std::string deck = split == std::string::npos ? text : text.substr(0, split);
  const std::string part = split == std::string::npos ? "" : text.substr(split + marker.size());
  const std::string deck_path = styk::fuzz::scratch_path("deck.inp");
  styk::fuzz::write_bytes(deck_path, reinterpret_cast<const std::uint8_t*>(deck.data()),
                          deck.size());
  styk::fuzz::write_bytes(styk::fuzz::scratch_path("part.inp"),
                          reinterpret_cast<const std::uint8_t*>(part.data()), part.size());
  try {
    (void)styk::read_inp(deck_path, registry());
  } catch (const styk::InputError&) {
  } catch (const styk::ResourceLimitError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: read_inp threw %s\n", e.what());
    std::abort();
  }
  return 0;
}
