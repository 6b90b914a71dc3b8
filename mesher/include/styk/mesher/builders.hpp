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
#include "styk/mesher/mesh.hpp"

namespace styk::mesher {

struct ParamDecl {
  std::string name;  // without the leading "--"
  std::string default_value;
  std::string help;
};

// The values of one builder run (defaults filled in), with typed access. Bad values throw
// InputError at "styk mesh BUILDER" naming the parameter.
class BuilderParams {
 public:
  BuilderParams(std::string builder, std::map<std::string, std::string> values);
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;
  double positive(const std::string& name) const;
  int count(const std::string& name, int minimum = 1) const;
  const std::string& choice(const std::string& name, const std::vector<std::string>& allowed) const;
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string builder_;
  std::map<std::string, std::string> values_;
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
// it must know the element family asked for (load the plug-ins for C3D14/C3D21/C3D28).
BuildResult run_builder(const std::string& name, const std::map<std::string, std::string>& args,
                        const ElementRegistry& registry);

}  // namespace styk::mesher
