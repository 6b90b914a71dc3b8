#include <chrono>
#include <map>
#include <string>

#include <fmt/core.h>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "mesh_args.hpp"
#include "registry_setup.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/studies/static_solve.hpp"

namespace styk::cli {
namespace {

void print_catalogue() {
  for (const mesher::BuilderInfo& b : mesher::builder_catalogue()) {
    fmt::print("{:<16} {:<8} {}\n", b.name, b.section, b.title);
    for (const mesher::ParamDecl& p : b.params)
      fmt::print("    --{:<10} {:<10} {}\n", p.name, p.default_value, p.help);
  }
}

// "--name value" and "--name=value" pairs.
std::map<std::string, std::string> parse_params(const MeshArgs& args) {
  const SourceLoc here{"styk mesh " + args.builder, 0};
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < args.params.size(); ++i) {
    const std::string& a = args.params[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0)
      throw InputError(here, "expected --name value, not '" + a + "'");
    std::string name = a.substr(2), value;
    const std::size_t eq = name.find('=');
    if (eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else {
      if (i + 1 >= args.params.size()) throw InputError(here, "--" + name + " needs a value");
      value = args.params[++i];
    }
    if (!out.emplace(name, value).second) throw InputError(here, "--" + name + " given twice");
  }
  return out;
}

}  // namespace

int mesh_command(const MeshArgs& args) {
  if (args.list) {
    print_catalogue();
    return kOk;
  }
  if (args.builder.empty())
    throw InputError({"styk mesh", 0}, "name a builder (styk mesh --list shows them)");
  if (args.output.empty())
    throw InputError({"styk mesh " + args.builder, 0}, "-o FILE.inp is required");
  const std::map<std::string, std::string> params = parse_params(args);
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  // Some builders solve (the bolted flange calibrates its preload), so say what is running.
  fmt::print(stderr, "building {} ...\n", args.builder);
  const auto start = std::chrono::steady_clock::now();
  const mesher::BuildResult result =
      mesher::run_builder(args.builder, params, registry, studies::static_solve(registry));
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  fmt::print(stderr, "built {} in {:.1f} s\n", args.builder, took.count());
  AtomicTextFile file(args.output);
  write_inp(result.model, file.stream());
  file.commit();
  // Steady heat / electric-potential decks have one unknown per node, mechanical ones three.
  bool scalar = false;
  for (const Step& step : result.model.steps) scalar |= step.kind != StepKind::Static;
  fmt::print("{}: {} nodes, {} elements, {} DOFs\n", args.output, result.model.node_count(),
             result.model.element_count(), (scalar ? 1 : 3) * result.model.node_count());
  if (!result.note.empty()) fmt::print("note: {}\n", result.note);
  return kOk;
}

}  // namespace styk::cli
