// styk: the command-line front end. Parses arguments (CLI11 lives only in this file) and hands
// them to the sub-commands.
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mesh_args.hpp"
#include "study_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "verify_args.hpp"
#ifdef STYK_WITH_RENDER
#include "render_args.hpp"
#include "styk/io/temp_file.hpp"
#endif

int main(int argc, char** argv) {
  using namespace styk::cli;
  // An interrupted run (Ctrl-C, kill, the GUI's Cancel) leaves no temporary behind, and a
  // file-size limit fails the write with a message instead of killing the process.
  styk::io::remove_temporaries_on_signals();
  styk::io::skip_hdf5_shutdown_at_exit();
  CLI::App app{"Styk: finite-element analysis of contact in machine joints"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "styk 0.1.0");

  SolveArgs solve;
  CLI::App* solve_cmd =
      app.add_subcommand("solve", "Solve an .inp model; write MODEL.styk.h5 and MODEL.dat");
  solve_cmd->add_option("model", solve.deck, "Input deck (.inp)")->required();
  solve_cmd->add_option("-o,--output-dir", solve.output_dir,
                        "Directory for the results (default: current)");
  solve_cmd
      ->add_option("--solver", solve.solver,
                   "Linear solver: auto (by model size), cholmod (direct), iterative (CG + AMG); "
                   "overrides *STATIC, SOLVER=")
      ->check(CLI::IsMember({"auto", "cholmod", "iterative"}));
  solve_cmd
      ->add_option("--contact-solver", solve.contact_solver,
                   "Contact iteration: auto, dense (the compliance over the contact rows; fastest "
                   "while it fits), sparse (one sparse LU of K with the closed rows per "
                   "iteration; for thousands of contact nodes); auto picks sparse when the dense "
                   "compliance would pass a quarter of the memory limit or a sparse step is "
                   "expected to be cheaper")
      ->check(CLI::IsMember({"auto", "dense", "sparse"}));
  solve_cmd
      ->add_option("--threads", solve.threads, "Threads for assembly and recovery (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  solve_cmd
      ->add_option("--memory-limit", solve.memory_limit_gb,
                   "GB the direct solver's factor may take (default: 80 % of the memory); "
                   "above it auto switches to the iterative solver, cholmod stops")
      ->check(CLI::PositiveNumber);
  solve_cmd->add_flag("-q,--quiet", solve.quiet, "No progress lines on stderr");
  std::string progress_format = "text";
  solve_cmd
      ->add_option("--progress", progress_format,
                   "Progress on stderr: text (for people) or json (one JSON object per line, "
                   "docs/cli.md \"Progress protocol\")")
      ->check(CLI::IsMember({"text", "json"}));
  solve_cmd
      ->add_option("--ranks", solve.ranks,
                   "Solve across N MPI ranks on this machine: starts mpirun (or $STYK_MPIRUN) "
                   "itself; under mpirun the runner's -n decides")
      ->check(CLI::NonNegativeNumber);

  InfoArgs info;
  CLI::App* info_cmd = app.add_subcommand(
      "info", "Read an .inp model and print counts, sets, materials, steps, DOFs");
  info_cmd->add_option("model", info.deck, "Input deck (.inp)")->required();

  ExportArgs exp;
  bool vtu = false;
  bool frd = false;
  CLI::App* export_cmd =
      app.add_subcommand("export", "Export a results file (or a deck's mesh) for other programs");
  export_cmd->add_option("input", exp.input, "Results file (.styk.h5) or deck (.inp)")->required();
  CLI::Option* vtu_flag =
      export_cmd->add_flag("--vtu", vtu, "Write a VTK XML unstructured grid (.vtu) for ParaView");
  CLI::Option* frd_flag = export_cmd->add_flag(
      "--frd", frd, "Write a CalculiX results file (.frd) for cgx, PrePoMax, ccx2paraview");
  vtu_flag->excludes(frd_flag);
  export_cmd->add_option("-o,--output", exp.output,
                         "Output file (default: input name with .vtu or .frd)");
  export_cmd->add_option("--step", exp.step, "Step number (default: last; --frd: every step)")
      ->check(CLI::NonNegativeNumber);
  export_cmd
      ->add_option("--inc", exp.increment,
                   "Increment within the step (default: last; --frd: every increment)")
      ->check(CLI::NonNegativeNumber);

  ImportArgs import;
  CLI::App* import_cmd = app.add_subcommand(
      "import", "Convert a Gmsh mesh (.msh, ASCII 2.2 or 4.1) into a CalculiX mesh deck (.inp)");
  import_cmd->add_option("mesh", import.mesh, "Gmsh mesh (.msh)")->required();
  import_cmd->add_option("-o,--output", import.output,
                         "Deck to write (default: the mesh's name with .inp)");
  import_cmd->add_option("--planar", import.planar,
                         "A surface mesh's elements: cps (plane stress), cpe (plane strain), cax "
                         "(axisymmetric) or shell");
  import_cmd->add_option("--lines", import.lines,
                         "A line mesh's elements: beam (B31/B32) or truss (T3D2)");

  CheckArgs check;
  CLI::App* check_cmd = app.add_subcommand(
      "check",
      "Verify a results file: schema, checksums, finite values, consistency; exit 0 if whole");
  check_cmd->add_option("results", check.results, "Results file (.styk.h5)")->required();

  MeshArgs mesh;
  CLI::App* mesh_cmd = app.add_subcommand(
      "mesh", "Build a SPEC.md model with a parametric builder and write its deck");
  mesh_cmd->add_option("builder", mesh.builder, "Builder name (see --list)");
  mesh_cmd->add_option("-o,--output", mesh.output, "Deck to write (.inp)");
  mesh_cmd->add_flag("--list", mesh.list, "List the builders, their SPEC sections and parameters");
  mesh_cmd->allow_extras();  // builder parameters: --name value (checked by the builder)

#ifdef STYK_WITH_RENDER
  RenderArgs render;
  CLI::App* render_cmd = app.add_subcommand(
      "render", "Draw a results file (or a deck's mesh) headless into a PNG or BMP");
  render_cmd->add_option("input", render.input, "Results file (.styk.h5) or deck (.inp, mesh only)")
      ->required();
  render_cmd->add_option(
      "-o,--output", render.output,
      "Picture (.png or .bmp; .gif/.mp4 with --animate and ffmpeg); default: input name with .png");
  render_cmd->add_option("--step", render.step, "Step number (default: last)")
      ->check(CLI::NonNegativeNumber);
  render_cmd->add_option("--inc", render.increment, "Increment within the step (default: last)")
      ->check(CLI::NonNegativeNumber);
  render_cmd->add_option(
      "--field", render.field,
      "Contour field: U, U.x, RF.mag, S.mises, S.p1, S.11, E.22, ... (default: none)");
  render_cmd->add_option("--averaging", render.averaging,
                         "Stress/strain averaging: none, I, II, centroid (default: II)");
  render_cmd->add_option(
      "--fibre", render.fibre,
      "Shells: the fibre whose stress/strain is drawn: bottom, middle, top (default: top)");
  render_cmd->add_option("--bands", render.bands, "Contour colours, 2..24 (default: 12)")
      ->check(CLI::Range(2, 24));
  render_cmd->add_flag("--smooth", render.smooth, "Continuous colours instead of bands");
  render_cmd->add_flag("--contact-only", render.contact_only,
                       "With a contact field: draw only the faces that carry contact output");
  render_cmd->add_flag(
      "--all-faces", render.all_faces,
      "With a contact field: draw every face even where the contact faces are hidden");
  render_cmd->add_option("--contact-pair", render.contact_pair,
                         "With a contact field: one *CONTACT PAIR's output, by its slave surface "
                         "or number (1, 2, ...)");
  render_cmd->add_option(
      "--range", render.range,
      "Colour scale MIN,MAX (default: the field's range over the shown elements)");
  render_cmd->add_flag(
      "--ip-values", render.ip_values,
      "Draw the field's integration-point values as coloured points over the mesh");
  render_cmd->add_option("--labels", render.labels,
                         "Numbers of the seen entities: nodes, elements or nodes,elements");
  render_cmd->add_flag(
      "--unroll", render.unroll,
      "Unrolled map of a contact field over (angle, axial position), or (x, y) on a flat surface");
  render_cmd->add_option("--unroll-axis", render.unroll_axis,
                         "The fit's axis for --unroll: PX,PY,PZ,DX,DY,DZ (default: fitted)");
  render_cmd
      ->add_option("--samples", render.samples,
                   "Samples per pixel smoothing the edges, 1..16 (default: 4)")
      ->check(CLI::Range(1, 16));
  render_cmd->add_option("--deform", render.deform,
                         "Deformation scale: auto, none or a factor (default: auto with results)");
  render_cmd->add_flag("--no-outline", render.no_outline,
                       "No undeformed outline under the deformed shape");
  render_cmd->add_option("--mode", render.mode,
                         "points, wireframe, hidden, shaded, shaded-edges (default: shaded)");
  render_cmd->add_option("--view", render.view, "iso, +x, -x, +y, -y, +z, -z (default: iso)");
  render_cmd->add_option("--azimuth", render.azimuth,
                         "Turn the view about the screen vertical, degrees");
  render_cmd->add_option("--elevation", render.elevation,
                         "Raise the eye about the screen horizontal, degrees");
  render_cmd->add_option("--zoom", render.zoom, "Zoom factor (> 1 enlarges)")
      ->check(CLI::PositiveNumber);
  render_cmd->add_flag("--perspective", render.perspective,
                       "Perspective instead of orthographic projection");
  render_cmd->add_option("--layers", render.layers,
                         "Element sets shown as layers, comma-separated (default: whole model)");
  render_cmd->add_option("--hide-layers", render.hide_layers,
                         "Layers (among --layers) not shown, comma-separated");
  render_cmd->add_option("--elements", render.elements, "Element id range FIRST-LAST");
  render_cmd->add_option("--types", render.types, "Element types, comma-separated");
  render_cmd->add_option("--size", render.size, "Picture size WIDTHxHEIGHT (default: 1600x1200)");
  render_cmd
      ->add_option("--revolve", render.revolve,
                   "Draw axisymmetric elements (CAX...) as the body swept about the y axis through "
                   "this many degrees (0 < angle <= 360)")
      ->check(CLI::Range(0.0, 360.0));
  render_cmd
      ->add_option("--revolve-segments", render.revolve_segments,
                   "Sectors of the --revolve sweep (default: one per 15 degrees)")
      ->check(CLI::PositiveNumber);
  render_cmd
      ->add_option("--animate", render.animate,
                   "Write N frames of the deformation from 0 to the scale")
      ->check(CLI::PositiveNumber);
#endif

  VerifyArgs verify;
  CLI::App* verify_cmd = app.add_subcommand(
      "verify", "Run the SPEC §3.1 element tests for every element; print or write Tab 3.13");
  verify_cmd->add_flag("--list", verify.list,
                       "List the test cases (SPEC section, builder, measure)");
  verify_cmd->add_option("--case", verify.case_name, "Run one case (see --list) for every element");
  verify_cmd->add_option("--table", verify.table, "Regenerate a table: 3.13 (SPEC §3.1.9 grades)");
  verify_cmd->add_option("--write", verify.write_path,
                         "With --table: replace the marked section of this Markdown file");

  StudyArgs study;
  CLI::App* study_cmd = app.add_subcommand(
      "study", "Studies: accuracy atlas, stability sweeps, model size, the SPEC §4 joint reports");
  study_cmd->require_subcommand(1);
  CLI::App* study_run =
      study_cmd->add_subcommand("run", "One run: build, solve, measure; print its CSV row");
  study_run->add_option("--study", study.study, "Study the run belongs to (recorded)");
  study_run->add_option("--problem", study.problem, "Problem or sweep (styk study accuracy --list)")
      ->required();
  study_run->add_option("--family", study.family, "Element family")->required();
  study_run->add_option("--level", study.level, "Refinement level (sweep: index of the value)")
      ->check(CLI::NonNegativeNumber);
  study_run->add_option("--repeats", study.repeats, "Timed solves (the median is kept)")
      ->check(CLI::PositiveNumber);
  for (const char* name : {"accuracy", "stability", "model-size"}) {
    CLI::App* sub = study_cmd->add_subcommand(
        name, std::string(name) == "accuracy"
                  ? "Refinement series of every element family on problems with exact solutions"
              : std::string(name) == "stability"
                  ? "Sweeps where methods fail: distortion, aspect ratio, nu -> 0.5"
                  : "The SPEC §4.2 shrink fit as full, quarter and sector models");
    sub->add_option("--problems", study.problems, "Problems to run (default: all)")->delimiter(',');
    sub->add_option("--families", study.families, "Element families (default: all available)")
        ->delimiter(',');
    sub->add_option("--max-dof", study.max_dof, "Stop a series before a level over this many DOF")
        ->check(CLI::PositiveNumber);
    sub->add_option("--max-seconds", study.max_seconds,
                    "Stop a series before a solve predicted slower than this")
        ->check(CLI::PositiveNumber);
    sub->add_option("--max-levels", study.max_levels, "At most this many levels per series")
        ->check(CLI::NonNegativeNumber);
    sub->add_option("--repeats", study.repeats, "Timed solves per run (median kept)")
        ->check(CLI::PositiveNumber);
    sub->add_flag("--in-process", study.in_process, "Run in this process (no peak-memory figures)");
    sub->add_flag("--list", study.list, "List the problems and families");
    sub->add_option("-o,--output-dir", study.output_dir, "Directory for the CSV, charts and page");
    sub->add_option(
        "--docs", study.docs_dir,
        "Write the documentation: DIR/<study>.md, DIR/atlas/<study>.csv, DIR/images/atlas/");
    sub->add_option("--from-csv", study.from_csv,
                    "Draw the charts and page from this CSV, run nothing");
  }

  for (const char* name : {"shrink-fit", "conical-fit", "spline", "p3g", "bolted-flange"}) {
    CLI::App* sub = study_cmd->add_subcommand(
        name, std::string("SPEC §4 joint report (") + name +
                  "): build, solve, write the Markdown page, CSV and charts");
    sub->add_flag("--coarse", study.coarse, "Coarse meshes (the tests'): a quick look");
    sub->add_option("-o,--output-dir", study.output_dir, "Directory for the CSV, charts and page");
    sub->add_option("--docs", study.docs_dir,
                    "Write the documentation: DIR/joints/<study>.md and CSV, DIR/images/joints/");
  }

  app.add_subcommand("elements", "List the element types available, with rules and source");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  if (progress_format == "json") solve.progress = ProgressFormat::JsonLines;
  const ErrorOutput errors = *solve_cmd && solve.progress == ProgressFormat::JsonLines
                                 ? ErrorOutput::JsonLines
                                 : ErrorOutput::Text;
  return run_reporting_errors(
      [&]() -> int {
        if (*solve_cmd) return solve_command(solve);
        if (*info_cmd) return info_command(info);
        if (*export_cmd) {
          if (!vtu && !frd) throw styk::InputError({}, "styk export needs --vtu or --frd");
          exp.format = frd ? ExportFormat::Frd : ExportFormat::Vtu;
          return export_command(exp);
        }
        if (*import_cmd) return import_command(import);
        if (*check_cmd) return check_command(check);
#ifdef STYK_WITH_RENDER
        if (*render_cmd) return render_command(render);
#endif
        if (*mesh_cmd) {
          mesh.params = mesh_cmd->remaining();
          return mesh_command(mesh);
        }
        if (*verify_cmd) return verify_command(verify);
        if (*study_cmd) {
          for (CLI::App* sub : study_cmd->get_subcommands()) study.kind = sub->get_name();
          return study_command(study);
        }
        return elements_command();
      },
      errors);
}
