#include "model_dialogs.hpp"

#include <QApplication>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <algorithm>
#include <cstdlib>
#include <map>

#include "child_process_solve.hpp"
#include "dialog_fields.hpp"
#include "session/brick_types.hpp"
#include "session/entry_edits.hpp"
#include "session/input_checks.hpp"
#include "session/validation.hpp"
#include "solve_runner.hpp"
#include "styk/mesher/builders.hpp"

namespace styk::gui {
namespace {

// The wait cursor for as long as it lives (a builder may calibrate with a solve).
struct BusyCursor {
  BusyCursor() { QApplication::setOverrideCursor(Qt::WaitCursor); }
  ~BusyCursor() { QApplication::restoreOverrideCursor(); }
  BusyCursor(const BusyCursor&) = delete;
  BusyCursor& operator=(const BusyCursor&) = delete;
};

QStringList element_sets(const Model& m) { return element_set_names(m); }
QStringList materials(const Model& m) { return material_names(m); }

// `count` numbers separated by blanks, commas or semicolons, or InputError naming the field.
std::vector<double> numbers(const std::string& text, const std::string& label, int count) {
  const QStringList parts =
      QString::fromStdString(text).split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts);
  if (parts.size() != count)
    throw InputError({}, label + ": give " + std::to_string(count) + " numbers, not " +
                             std::to_string(parts.size()));
  std::vector<double> v;
  for (const QString& p : parts) v.push_back(parse_real(p.toStdString(), label));
  return v;
}

// The block dialog's box or corners (whichever "use_corners" selects) into `in`.
void read_block_corners(const FormDialog& f, BlockInput& in) {
  in.use_corners = f.checked("use_corners");
  if (in.use_corners) {
    const std::vector<double> c = numbers(f.text("corners"), "Corners", 24);
    for (int i = 0; i < 8; ++i) in.corners[i] = {c[3 * i], c[3 * i + 1], c[3 * i + 2]};
  } else {
    const std::vector<double> o = numbers(f.text("origin"), "Box origin", 3);
    const std::vector<double> s = numbers(f.text("size"), "Box size", 3);
    in.origin = {o[0], o[1], o[2]};
    in.size = {s[0], s[1], s[2]};
  }
}

// "x y z; x y z; ...": one point per semicolon, so the user finds the edge to curve.
QString point_list(const std::vector<Vec3>& points) {
  QStringList text;
  for (const Vec3& p : points)
    text << QString("%1 %2 %3").arg(p[0], 0, 'g', 12).arg(p[1], 0, 'g', 12).arg(p[2], 0, 'g', 12);
  return text.join("; ");
}

// "Fill midpoints": the straight-edge midpoints of the current box or corners, the starting
// point for curving some of the edges. Bad corners are shown in the dialog's error line.
void add_fill_midpoints_button(FormDialog& d) {
  auto* button = new QPushButton("Fill midpoints from the box / corners");
  button->setObjectName("fill_midpoints");
  d.findChild<QFormLayout*>()->addRow(QString(), button);
  QObject::connect(button, &QPushButton::clicked, &d, [&d] {
    auto* error = d.findChild<QLabel*>("error");
    try {
      BlockInput in;
      read_block_corners(d, in);
      d.findChild<QLineEdit*>("mid_edges")->setText(point_list(straight_mid_edges(in)));
      error->clear();
    } catch (const InputError& e) {
      error->setText(QString::fromStdString(e.message()));
    }
  });
}

}  // namespace

FormDialog* make_block_dialog(Document& doc, QWidget* parent) {
  auto* d = new FormDialog("Mesh block",
                           "A hexahedral block, meshed and added to the model. Give a box "
                           "(origin and size) or the 8 corners (C3D8 order, x y z each). Curved "
                           "edges: the 12 mid-edge points (C3D20 nodes 9-20, x y z each); each "
                           "edge becomes the quadratic through its corners and its mid-edge "
                           "point. The element set NAME and node sets/surfaces NAME_XMIN ... "
                           "NAME_ZMAX are created.",
                           parent);
  d->add_text("name", "Name (element set)", "BLOCK");
  d->add_text("origin", "Box origin x y z", "0 0 0");
  d->add_text("size", "Box size x y z", "100 10 10");
  d->add_check("use_corners", "Use the 8 corners below instead of the box", false);
  d->add_text("corners", "Corners (24 numbers)", "");
  d->add_check("curved", "Curved edges (20 points): use the mid-edge points below", false);
  BlockInput box;
  box.size = {100, 10, 10};
  d->add_text("mid_edges", "Mid-edge points (nodes 9-20, 36 numbers)",
              point_list(straight_mid_edges(box)));
  add_fill_midpoints_button(*d);
  d->add_text("divisions", "Divisions x y z", "10 2 2");
  d->add_text("grading", "Grading x y z (last/first)", "1 1 1");
  QStringList types;
  for (const std::string& type : brick_types(doc.registry())) types << QString::fromStdString(type);
  d->add_choice("type", "Element type", types);
  d->add_choice("layer_side", "Contact layer (C3D21, C3D28, ...) on side",
                {"ZMAX", "ZMIN", "XMIN", "XMAX", "YMIN", "YMAX"});
  d->add_choice("material", "Section material", QStringList{"(none)"} + materials(doc.model()));
  d->set_accept([&doc](const FormDialog& f) {
    BlockInput in;
    in.name = f.text("name");
    read_block_corners(f, in);
    if (f.checked("curved")) {
      const std::vector<double> m = numbers(f.text("mid_edges"), "Mid-edge points", 36);
      for (int i = 0; i < 12; ++i) in.mid_edges.push_back({m[3 * i], m[3 * i + 1], m[3 * i + 2]});
    }
    const QStringList div = QString::fromStdString(f.text("divisions"))
                                .split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts);
    if (div.size() != 3) throw InputError({}, "Divisions: give 3 whole numbers");
    for (int k = 0; k < 3; ++k) in.divisions[k] = parse_integer(div[k].toStdString(), "Divisions");
    const std::vector<double> g = numbers(f.text("grading"), "Grading", 3);
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
    d->add_text(QString::fromStdString(p.name), QString::fromStdString(p.name + " — " + p.help),
                QString::fromStdString(p.default_value));
  const std::vector<mesher::ParamDecl> params = it->params;
  d->set_accept([&doc, builder, params](const FormDialog& f) {
    std::map<std::string, std::string> args;
    for (const mesher::ParamDecl& p : params) args[p.name] = f.text(QString::fromStdString(p.name));
    // A calibrating builder (the bolted flange's preload) solves through `styk solve`.
    const BusyCursor busy;
    mesher::BuildResult built = mesher::run_builder(
        builder, args, doc.registry(), child_process_solve(SolveRunner::locate_styk_program()));
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
                                         : MaterialInput{"STEEL", 210000.0, 0.3, 0.0, 0.0, {}, {}};
  const auto values = [](const std::vector<double>& k) {
    QStringList parts;
    for (double v : k) parts << QString::number(v);
    return parts.join(' ');
  };
  auto* d = new FormDialog(material >= 0 ? "Edit material" : "Material",
                           "Isotropic linear elastic material, optionally with thermal expansion "
                           "(*EXPANSION: mean coefficient from temperature 0), and for heat "
                           "transfer / electric conduction steps the conductivities (one value: "
                           "isotropic; three: k11 k22 k33 in global axes; empty: none). E = 0: no "
                           "elastic constants (a heat or electric material). Renaming updates the "
                           "sections that use it.",
                           parent);
  d->add_text("name", "Name", QString::fromStdString(in.name));
  d->add_text("young", "Young's modulus E", QString::number(in.young));
  d->add_text("poisson", "Poisson's ratio", QString::number(in.poisson));
  d->add_text("density", "Density (0: none)", QString::number(in.density));
  d->add_text("expansion", "Expansion coefficient (0: none)", QString::number(in.expansion));
  d->add_text("conductivity", "Conductivity k (*CONDUCTIVITY)", values(in.conductivity));
  d->add_text("electrical", "Electrical conductivity", values(in.electrical_conductivity));
  d->set_accept([&doc, material](const FormDialog& f) {
    const auto list = [&f](const QString& key, const QString& label) {
      std::vector<double> v;
      for (const QString& p : QString::fromStdString(f.text(key))
                                  .split(QRegularExpression("[\\s,;]+"), Qt::SkipEmptyParts))
        v.push_back(parse_real(p.toStdString(), label.toStdString()));
      return v;
    };
    const MaterialInput edited{f.text("name"),
                               f.real("young", "Young's modulus"),
                               f.real("poisson", "Poisson's ratio"),
                               f.real("density", "Density"),
                               f.real("expansion", "Expansion coefficient"),
                               list("conductivity", "Conductivity"),
                               list("electrical", "Electrical conductivity")};
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
  auto* d = new FormDialog(step >= 0 ? "Edit step" : "Step",
                           "A step: linear static (*STATIC), steady heat transfer (*HEAT "
                           "TRANSFER, STEADY STATE: temperature, dof 11) or electric conduction "
                           "(*COUPLED THERMAL-ELECTRICAL, STEADY STATE: potential, dof 9).",
                           parent);
  const QStringList kinds{"static", "heat transfer", "electric conduction"};
  if (step >= 0) {
    const Step& s = m.steps.at(step);
    d->add_text("name", "Name", QString::fromStdString(s.name));
    d->add_choice("kind", "Kind", kinds, QString::fromStdString(step_kind_name(s.kind)));
    d->add_text("initial", "Initial increment", QString::number(s.procedure.initial_increment));
    d->add_text("total", "Total time", QString::number(s.procedure.total_time));
  } else {
    d->add_text("name", "Name", QString("STEP-%1").arg(m.steps.size() + 1));
    d->add_choice("kind", "Kind", kinds);
    d->add_text("initial", "Initial increment", "1");
    d->add_text("total", "Total time", "1");
  }
  d->set_accept([&doc, step](const FormDialog& f) {
    const StepInput in{f.text("name"), f.real("initial", "Initial increment"),
                       f.real("total", "Total time"), step_kind_of(f.text("kind"))};
    doc.apply(step >= 0 ? step_edit_command(doc.model(), step, in) : step_command(doc.model(), in));
  });
  return d;
}

}  // namespace styk::gui
