// styk: the command-line front end. Parses arguments (CLI11 lives only in this file) and hands
// them to the sub-commands.
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mesh_args.hpp"

int main(int argc, char** argv) {
  using namespace styk::cli;
  CLI::App app{"Styk: finite-element analysis of contact in machine joints"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "styk 0.1.0");

  SolveArgs solve;
  CLI::App* solve_cmd = app.add_subcommand("solve", "Solve an .inp model; write MODEL.styk.h5 and MODEL.dat");
  solve_cmd->add_option("model", solve.deck, "Input deck (.inp)")->required();
  solve_cmd->add_option("-o,--output-dir", solve.output_dir, "Directory for the results (default: current)");
  solve_cmd->add_option("--solver", solve.solver,
                        "Linear solver: auto (by model size), cholmod (direct), iterative (CG + AMG); "
                        "overrides *STATIC, SOLVER=")
      ->check(CLI::IsMember({"auto", "cholmod", "iterative"}));
  solve_cmd->add_option("--threads", solve.threads, "Threads for assembly and recovery (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  solve_cmd->add_flag("-q,--quiet", solve.quiet, "No progress lines on stderr");

  InfoArgs info;
  CLI::App* info_cmd = app.add_subcommand("info", "Read an .inp model and print counts, sets, materials, steps, DOFs");
  info_cmd->add_option("model", info.deck, "Input deck (.inp)")->required();

  ExportArgs exp;
  bool vtu = false;
  CLI::App* export_cmd = app.add_subcommand("export", "Export a results file (or a deck's mesh) for other programs");
  export_cmd->add_option("input", exp.input, "Results file (.styk.h5) or deck (.inp)")->required();
  export_cmd->add_flag("--vtu", vtu, "Write a VTK XML unstructured grid (.vtu) for ParaView")->required();
  export_cmd->add_option("-o,--output", exp.output, "Output file (default: input name with .vtu)");
  export_cmd->add_option("--step", exp.step, "Step number (default: last)")->check(CLI::NonNegativeNumber);
  export_cmd->add_option("--inc", exp.increment, "Increment within the step (default: last)")
      ->check(CLI::NonNegativeNumber);

  MeshArgs mesh;
  CLI::App* mesh_cmd = app.add_subcommand(
      "mesh", "Build a SPEC.md model with a parametric builder and write its deck");
  mesh_cmd->add_option("builder", mesh.builder, "Builder name (see --list)");
  mesh_cmd->add_option("-o,--output", mesh.output, "Deck to write (.inp)");
  mesh_cmd->add_flag("--list", mesh.list, "List the builders, their SPEC sections and parameters");
  mesh_cmd->allow_extras();  // builder parameters: --name value (checked by the builder)

  app.add_subcommand("elements", "List the element types available, with rules and source");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  return run_reporting_errors([&]() -> int {
    if (*solve_cmd) return solve_command(solve);
    if (*info_cmd) return info_command(info);
    if (*export_cmd) return export_command(exp);
    if (*mesh_cmd) {
      mesh.params = mesh_cmd->remaining();
      return mesh_command(mesh);
    }
    return elements_command();
  });
}
