#include <iostream>

#include <fmt/core.h>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "registry_setup.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/frd_writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/vtu_export.hpp"

namespace styk::cli {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string default_output(const std::string& input, const std::string& extension) {
  for (const char* ext : {".styk.h5", ".inp", ".INP"})
    if (ends_with(input, ext))
      return input.substr(0, input.size() - std::string(ext).size()) + extension;
  return input + extension;
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

// The job name on the .frd's first line: the file name without directory and extension.
std::string job_of(const std::string& output) {
  std::string name = output.substr(output.find_last_of('/') + 1);
  if (ends_with(name, ".frd")) name.resize(name.size() - 4);
  return name;
}

// .frd: every increment the results hold (or those of --step / --inc), every field they hold.
int export_frd(const ExportArgs& args, const std::string& output, const ElementRegistry& registry) {
  if (ends_with(args.input, ".styk.h5")) {
    const ResultsFileContents contents = read_results_file(args.input);
    if (!contents.verified) std::cerr << unverified_notice(args.input) << "\n";
    int step = 0;
    if (args.step > 0 || args.increment > 0)  // as for VTU: the last step unless --step says
      step = pick_increment(contents.results, args.step, args.increment, args.input).step;
    const FrdPlan plan = frd_plan_everything(contents.results, step, args.increment);
    write_frd(output, contents.model, registry, plan, job_of(output));
  } else {
    const Model model = read_inp(args.input, registry);
    write_frd(output, model, registry, FrdPlan{}, job_of(output));
  }
  std::cout << "wrote " << output << "\n";
  return kOk;
}

}  // namespace

int export_command(const ExportArgs& args) {
  const bool frd = args.format == ExportFormat::Frd;
  const std::string output =
      args.output.empty() ? default_output(args.input, frd ? ".frd" : ".vtu") : args.output;
  // Every element is written as the VTK cell its formulation describes: plug-ins included.
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  if (frd) return export_frd(args, output, registry);
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
