// The parametric builders of the SPEC.md models (`styk mesh NAME --param value ...`). Each
// builder declares its parameters once (name, default, help); the CLI, --list and docs/mesher.md
// are driven from that declaration. Defaults reproduce the thesis' element counts.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

// A linear static solve of a whole model. The mesher never solves; a builder that calibrates its
// deck with a solve (the bolted flange's preload) gets one from the layer above it, which builds
// AND solves (studies::static_solve, or a GUI that runs `styk solve`), through BuilderParams.
using StaticSolve = std::function<Results(const Model&)>;

struct ParamDecl {
  std::string name;  // without the leading "--"
  std::string default_value;
  std::string help;
};

// The values of one builder run (defaults filled in), with typed access, and the solve the caller
// offers (may be empty). Bad values throw InputError at "styk mesh BUILDER" naming the parameter.
class BuilderParams {
 public:
  BuilderParams(std::string builder, std::map<std::string, std::string> values,
                StaticSolve solve = {});
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;
  double positive(const std::string& name) const;
  int count(const std::string& name, int minimum = 1) const;
  const std::string& choice(const std::string& name, const std::vector<std::string>& allowed) const;
  [[noreturn]] void fail(const std::string& message) const;
  // Solves `model` with the caller's solve; without one, fails naming `option` (the parameter
  // setting that asked for the solve) and `alternative` (the setting that needs none).
  Results solve(const Model& model, const std::string& option,
                const std::string& alternative) const;

 private:
  std::string builder_;
  std::map<std::string, std::string> values_;
  StaticSolve solve_;
};

struct BuildResult {
  Model model;       // the deck: mesh, sets, material, section, BCs, one static step
  Mesh mesh;         // the mesh with surfaces (element indices = model element indices)
  std::string note;  // what the deck does not (yet) contain, for the user
};

struct BuilderInfo {
  std::string name;
  std::string section;  // "§3.1.4"
  std::string title;
  std::vector<ParamDecl> params;
  std::function<BuildResult(const BuilderParams&, const ElementRegistry&)> build;
};

// Every builder, in SPEC order.
std::vector<BuilderInfo> builder_catalogue();

// Runs builder `name` with `args` (parameter name -> value; unknown names, unknown builders and
// bad values throw InputError). The registry supplies the face integrals of consistent loads, so
// it must know the element family asked for (load the plug-ins for C3D14/C3D21/C3D28). `solve`
// serves the builders that calibrate with a solve; without it they refuse such settings.
BuildResult run_builder(const std::string& name, const std::map<std::string, std::string>& args,
                        const ElementRegistry& registry, StaticSolve solve = {});

}  // namespace styk::mesher
