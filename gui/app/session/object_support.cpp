#include "session/object_support.hpp"

#include <numeric>
#include <vector>

#include "session/input_checks.hpp"

namespace styk::gui::objects {

bool is_shell_type(const std::string& type, const ElementRegistry& registry) {
  const TElement* f = registry.find(type);
  return f != nullptr && f->form() == ElementForm::Shell;
}

void check_divisions(int d, const std::string& what, int most) {
  if (d < 1) refuse(what + " divisions must be at least 1, not " + std::to_string(d));
  if (d > most) refuse(what + " divisions must be at most " + std::to_string(most));
}

void check_grading(double g, const std::string& what) {
  check_finite(g, what + " grading");
  if (!(g > 0)) refuse(what + " grading must be > 0 (last / first element length; 1 = uniform)");
}

void check_object_names(const Model& model, const std::string& name, const std::string& what) {
  check_name(name, what);
  const std::string upper = to_upper(name);
  if (model.find_elset(upper) || model.find_nset(upper))
    refuse("a set " + upper + " exists already; choose another name");
  check_set_names_free(model, upper);
}

void check_section(const Model& model, const std::string& material, double value,
                   const std::string& what) {
  if (material.empty()) return;
  if (model.material_index(to_upper(material)) < 0)
    refuse("no material " + to_upper(material) + " in the model");
  check_finite(value, what);
  if (!(value > 0)) refuse(what + " must be > 0");
}

Model append_object(const Model& model, mesher::Mesh& mesh, const std::string& name,
                    const std::string& material, double value, std::optional<double> shell,
                    std::optional<BeamSection> beam) {
  std::vector<int> all(mesh.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  mesh.add_to_node_set(name, all);
  Model result = model;
  append_part(result, mesher::to_model(mesh));
  if (!material.empty()) {
    Section section;
    section.elset = name;
    section.material = to_upper(material);
    section.material_index = result.material_index(section.material);
    if (!beam) section.thickness = value;
    if (shell) section.shell = ShellSection{*shell, 5, false};
    section.beam = beam;
    const int index = static_cast<int>(result.sections.size());
    result.sections.push_back(section);
    for (int e : result.elsets.at(name).elements) result.elements[e].section = index;
  }
  return result;
}

}  // namespace styk::gui::objects
