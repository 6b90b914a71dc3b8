#include "model_dialogs.hpp"

#include <QRegularExpression>
#include <algorithm>
#include <cstdlib>
#include <map>

#include "dialog_fields.hpp"
#include "session/entry_edits.hpp"
#include "session/validation.hpp"
#include "styk/mesher/builders.hpp"

namespace styk::gui {
namespace {

QStringList node_sets(const Model& m) { return node_set_names(m); }
QStringList element_sets(const Model& m) { return element_set_names(m); }
QStringList materials(const Model& m) { return material_names(m); }
QStringList steps(const Model& m, bool model_level) { return step_names(m, model_level); }

}  // namespace

FormDialog* make_block_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Mesh block",
                           "A hexahedral block, meshed and added to the model. Give a box "
                           "(origin and size) or the 8 corners (C3D8 order, x y z each). The "
                           "element set NAME and node sets/surfaces NAME_XMIN ... NAME_ZMAX are "
                           "created.",
                           parent);
  d->add_text("name", "Name (element set)", "BLOCK");
  d->add_text("origin", "Box origin x y z", "0 0 0");
  d->add_text("size", "Box size x y z", "100 10 10");
  d->add_check("use_corners", "Use the 8 corners below instead of the box", false);
  d->add_text("corners", "Corners (24 numbers)", "");
  d->add_text("divisions", "Divisions x y z", "10 2 2");
  d->add_text("grading", "Grading x y z (last/first)", "1 1 1");
  d->add_choice("type", "Element type", {"C3D20", "C3D8", "C3D21", "C3D28"});
  d->add_choice("layer_side", "C3D21/C3D28 layer on side",
                {"ZMAX", "ZMIN", "XMIN", "XMAX", "YMIN", "YMAX"});
  d->add_choice("material", "Section material", QStringList{"(none)"} + materials(doc.model()));
  d->set_accept([&doc](const FormDialog& f) {
    const auto numbers = [&f](const QString& key, const QString& label, int count) {
      const QStringList parts = QString::fromStdString(f.text(key))
                                    .split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts);
      if (parts.size() != count)
        throw InputError({}, label.toStdString() + ": give " + std::to_string(count) +
                                 " numbers, not " + std::to_string(parts.size()));
      std::vector<double> v;
      for (const QString& p : parts) v.push_back(parse_real(p.toStdString(), label.toStdString()));
      return v;
    };
    BlockInput in;
    in.name = f.text("name");
    in.use_corners = f.checked("use_corners");
    if (in.use_corners) {
      const std::vector<double> c = numbers("corners", "Corners", 24);
      for (int i = 0; i < 8; ++i) in.corners[i] = {c[3 * i], c[3 * i + 1], c[3 * i + 2]};
    } else {
      const std::vector<double> o = numbers("origin", "Box origin", 3);
      const std::vector<double> s = numbers("size", "Box size", 3);
      in.origin = {o[0], o[1], o[2]};
      in.size = {s[0], s[1], s[2]};
    }
    const QStringList div = QString::fromStdString(f.text("divisions"))
                                .split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts);
    if (div.size() != 3) throw InputError({}, "Divisions: give 3 whole numbers");
    for (int k = 0; k < 3; ++k) in.divisions[k] = parse_integer(div[k].toStdString(), "Divisions");
    const std::vector<double> g = numbers("grading", "Grading", 3);
    in.grading = {g[0], g[1], g[2]};
    in.type = f.text("type");
    in.layer_side = f.text("layer_side");
    in.material = f.text("material") == "(none)" ? std::string() : f.text("material");
    doc.apply(block_command(doc.model(), in, doc.registry()));
  });
  return d;
}

FormDialog* make_builder_dialog(Document& doc, const std::string& builder, QWidget* parent) {
  const std::vector<mesher::BuilderInfo> catalogue = mesher::builder_catalogue();
  const auto it = std::find_if(catalogue.begin(), catalogue.end(),
                               [&](const mesher::BuilderInfo& b) { return b.name == builder; });
  if (it == catalogue.end()) return nullptr;
  auto* d = new FormDialog(QString::fromStdString("Model from builder " + it->name),
                           QString::fromStdString(it->section + " " + it->title +
                                                  ". The builder's deck replaces the model (undo "
                                                  "brings it back)."),
                           parent);
  for (const mesher::ParamDecl& p : it->params)
    d->add_text(QString::fromStdString(p.name),
                QString::fromStdString(p.name + " — " + p.help),
                QString::fromStdString(p.default_value));
  const std::vector<mesher::ParamDecl> params = it->params;
  d->set_accept([&doc, builder, params](const FormDialog& f) {
    std::map<std::string, std::string> args;
    for (const mesher::ParamDecl& p : params) args[p.name] = f.text(QString::fromStdString(p.name));
    mesher::BuildResult built = mesher::run_builder(builder, args, doc.registry());
    built.model.source = builder + ".inp";
    doc.apply(make_replace_model("Build " + builder, doc.model(), std::move(built.model)));
  });
  return d;
}

FormDialog* make_material_dialog(Document& doc, QWidget* parent) {
  return make_material_dialog(doc, parent, -1);
}

FormDialog* make_material_dialog(Document& doc, QWidget* parent, int material) {
  const MaterialInput in = material >= 0 ? material_input_of(doc.model(), material)
                                         : MaterialInput{"STEEL", 210000.0, 0.3, 0.0, 0.0};
  auto* d = new FormDialog(material >= 0 ? "Edit material" : "Material",
                           "Isotropic linear elastic material, optionally with thermal expansion "
                           "(*EXPANSION: mean coefficient from temperature 0). Renaming updates "
                           "the sections that use it.",
                           parent);
  d->add_text("name", "Name", QString::fromStdString(in.name));
  d->add_text("young", "Young's modulus E", QString::number(in.young));
  d->add_text("poisson", "Poisson's ratio", QString::number(in.poisson));
  d->add_text("density", "Density (0: none)", QString::number(in.density));
  d->add_text("expansion", "Expansion coefficient (0: none)", QString::number(in.expansion));
  d->set_accept([&doc, material](const FormDialog& f) {
    const MaterialInput edited{f.text("name"), f.real("young", "Young's modulus"),
                               f.real("poisson", "Poisson's ratio"), f.real("density", "Density"),
                               f.real("expansion", "Expansion coefficient")};
    doc.apply(material >= 0 ? material_edit_command(doc.model(), material, edited)
                            : material_command(doc.model(), edited));
  });
  return d;
}

FormDialog* make_section_dialog(Document& doc, QWidget* parent) {
  return make_section_dialog(doc, parent, -1);
}

FormDialog* make_section_dialog(Document& doc, QWidget* parent, int section) {
  const Model& m = doc.model();
  auto* d = new FormDialog(section >= 0 ? "Edit solid section" : "Solid section",
                           "Assigns a material to an element set.", parent);
  if (section >= 0)
    d->add_choice("elset", "Element set", {QString::fromStdString(m.sections.at(section).elset)});
  else
    d->add_choice("elset", "Element set", element_sets(m));
  d->add_choice("material", "Material", materials(m),
                section >= 0 ? QString::fromStdString(m.sections[section].material) : QString());
  d->set_accept([&doc, section](const FormDialog& f) {
    doc.apply(section >= 0 ? section_edit_command(doc.model(), section, f.text("material"))
                           : section_command(doc.model(), {f.text("elset"), f.text("material")}));
  });
  return d;
}

FormDialog* make_step_dialog(Document& doc, QWidget* parent) {
  return make_step_dialog(doc, parent, -1);
}

FormDialog* make_step_dialog(Document& doc, QWidget* parent, int step) {
  const Model& m = doc.model();
  auto* d = new FormDialog(step >= 0 ? "Edit static step" : "Static step",
                           "A linear static step (*STEP, *STATIC).", parent);
  if (step >= 0) {
    const Step& s = m.steps.at(step);
    d->add_text("name", "Name", QString::fromStdString(s.name));
    d->add_text("initial", "Initial increment", QString::number(s.procedure.initial_increment));
    d->add_text("total", "Total time", QString::number(s.procedure.total_time));
  } else {
    d->add_text("name", "Name", QString("STEP-%1").arg(m.steps.size() + 1));
    d->add_text("initial", "Initial increment", "1");
    d->add_text("total", "Total time", "1");
  }
  d->set_accept([&doc, step](const FormDialog& f) {
    const StepInput in{f.text("name"), f.real("initial", "Initial increment"),
                       f.real("total", "Total time")};
    doc.apply(step >= 0 ? step_edit_command(doc.model(), step, in) : step_command(doc.model(), in));
  });
  return d;
}

FormDialog* make_boundary_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Boundary condition",
                           "Prescribes dofs first..last (1 = x, 2 = y, 3 = z) of every node of "
                           "a node set.",
                           parent);
  d->add_choice("nset", "Node set", node_sets(doc.model()));
  d->add_text("first", "First dof", "1");
  d->add_text("last", "Last dof", "3");
  d->add_text("value", "Value", "0");
  d->add_choice("step", "Step", steps(doc.model(), true));
  d->set_accept([&doc](const FormDialog& f) {
    doc.apply(boundary_command(doc.model(),
                               {f.text("nset"), f.integer("first", "First dof"),
                                f.integer("last", "Last dof"), f.real("value", "Value"),
                                step_index(f.text("step"))}));
  });
  return d;
}

FormDialog* make_cload_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Concentrated load", "*CLOAD on every node of a node set.", parent);
  d->add_choice("nset", "Node set", node_sets(doc.model()));
  d->add_text("dof", "Direction (1, 2, 3)", "3");
  d->add_text("value", "Value", "-100");
  d->add_check("split", "Value is the total, divided among the nodes", true);
  d->add_choice("step", "Step", steps(doc.model(), false));
  d->set_accept([&doc](const FormDialog& f) {
    doc.apply(cload_command(doc.model(), {f.text("nset"), f.integer("dof", "Direction"),
                                          f.real("value", "Value"), f.checked("split"),
                                          step_index(f.text("step"))}));
  });
  return d;
}

FormDialog* make_pressure_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Pressure",
                           "*DLOAD pressure (positive pushes into the element) on a surface, or "
                           "on face S1..S6 of every element of an element set.",
                           parent);
  QStringList surfaces{"(element set below)"};
  for (const auto& [name, s] : doc.model().surfaces) surfaces << QString::fromStdString(name);
  d->add_choice("surface", "Surface", surfaces);
  d->add_choice("elset", "Element set", element_sets(doc.model()));
  d->add_text("face", "Face (1..6)", "1");
  d->add_text("magnitude", "Pressure", "1");
  d->add_choice("step", "Step", steps(doc.model(), false));
  d->set_accept([&doc](const FormDialog& f) {
    const std::string surface = f.text("surface");
    doc.apply(pressure_command(
        doc.model(), {surface.rfind("(", 0) == 0 ? std::string() : surface, f.text("elset"),
                      f.integer("face", "Face"), f.real("magnitude", "Pressure"),
                      step_index(f.text("step"))}));
  });
  return d;
}

}  // namespace styk::gui
