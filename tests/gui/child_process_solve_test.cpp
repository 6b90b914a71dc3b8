// The builder dialog's solve (gui/app/src/child_process_solve.hpp): the desktop program does not
// link the solver, so a calibrating builder solves through `styk solve` as a child process. It must
// calibrate exactly as the in-process solve of `styk mesh` does, and report a failed solve as an
// InputError carrying the solver's own message.
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "box_model.hpp"
#include "child_process_solve.hpp"
#include "solve_runner.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/studies/static_solve.hpp"

namespace styk::gui {
namespace {

struct Registry {
  PluginLibraries libraries;
  ElementRegistry registry;
  Registry() { setup_element_registry(registry, libraries, {build_plugin_directory()}); }
};

// The shortening of the half bolt's cut end that step PRELOAD prescribes.
double preload_shortening(const Model& model) {
  for (const Step& step : model.steps)
    if (step.name == "PRELOAD") return step.boundaries.front().value;
  ADD_FAILURE() << "no PRELOAD step";
  return 0;
}

// SPEC §4.6 on a coarse mesh: the calibration through `styk solve` and the results file gives the
// in-process shortening to 1e-12 relative (the same solver, doubles stored exactly in HDF5).
TEST(ChildProcessSolve, BoltedFlangeCalibratesAsInProcess) {
  const Registry r;
  const std::map<std::string, std::string> coarse = {
      {"element", "C3D21"},  {"ring-layers", "2"}, {"neck-layers", "1"},  {"gasket-layers", "1"},
      {"shank-layers", "1"}, {"head-layers", "1"}, {"gasket-rings", "4"}, {"neck-rings", "1"}};
  const mesher::BuildResult child = mesher::run_builder(
      "bolted-flange", coarse, r.registry, child_process_solve(SolveRunner::locate_styk_program()));
  const mesher::BuildResult in_process =
      mesher::run_builder("bolted-flange", coarse, r.registry, studies::static_solve(r.registry));
  const double expected = preload_shortening(in_process.model);
  ASSERT_LT(expected, 0.0);
  EXPECT_NEAR(preload_shortening(child.model), expected, 1e-12 * std::abs(expected));
  EXPECT_NE(child.note.find("preload by calibration"), std::string::npos) << child.note;
}

// A model the solver refuses (a loaded box held nowhere: a mechanism) fails the build with the
// solver's exit status and message, not with an unreadable results file.
TEST(ChildProcessSolve, AFailedSolveCarriesTheSolversMessage) {
  Model model = test::box_model();
  Material steel;
  steel.name = "STEEL";
  steel.young = 210000;
  steel.poisson = 0.3;
  model.materials.push_back(steel);
  Section section;
  section.elset = "BOX";
  section.material = "STEEL";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;
  Step step;
  step.name = "LOAD";
  step.has_procedure = true;
  step.cloads.push_back({0, 1, 1.0, {}});
  model.steps.push_back(step);
  try {
    child_process_solve(SolveRunner::locate_styk_program())(model);
    ADD_FAILURE() << "a mechanism solved";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("styk solve failed (exit 1)"), std::string::npos) << what;
    EXPECT_NE(what.find("the model can move freely in x"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace styk::gui
