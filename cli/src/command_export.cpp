#include <iostream>

#include <fmt/core.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "registry_setup.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/vtu_export.hpp"

namespace styk::cli {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string default_output(const std::string& input) {
  for (const char* ext : {".styk.h5", ".inp", ".INP"})
    if (ends_with(input, ext))
      return input.substr(0, input.size() - std::string(ext).size()) + ".vtu";
  return input + ".vtu";
}

// The increment asked for: step 0 = last step, increment 0 = last increment of the step.
const IncrementResult& pick_increment(const Results& results, int step, int increment,
                                      const std::string& path) {
  if (results.increments.empty())
    throw InputError({path, 0}, "the results file holds no increments");
  const int want_step = step > 0 ? step : results.increments.back().step;
  const IncrementResult* found = nullptr;
  std::string available;
  for (const IncrementResult& inc : results.increments) {
    available += fmt::format(" {}/{}", inc.step, inc.increment);
    if (inc.step == want_step && (increment == 0 || inc.increment == increment)) found = &inc;
  }
  if (!found)
    throw InputError({path, 0},
                     fmt::format("no step {} increment {} in the results; step/increment "
                                 "available:{}",
                                 want_step, increment, available));
  return *found;
}

}  // namespace

int export_command(const ExportArgs& args) {
  const std::string output = args.output.empty() ? default_output(args.input) : args.output;
  // Every element is written as the VTK cell its formulation describes: plug-ins included.
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  if (ends_with(args.input, ".styk.h5")) {
    const ResultsFileContents contents = read_results_file(args.input);
    if (!contents.verified) std::cerr << unverified_notice(args.input) << "\n";
    const IncrementResult& inc =
        pick_increment(contents.results, args.step, args.increment, args.input);
    write_vtu(output, contents.model, registry, &inc);
  } else {
    const Model model = read_inp(args.input, registry);
    write_vtu(output, model, registry, nullptr);
  }
  std::cout << "wrote " << output << "\n";
  return kOk;
}

}  // namespace styk::cli
