#include "styk/inp/writer.hpp"

#include <array>
#include <optional>
#include <string>

#include "styk/core/beam_section.hpp"
#include "styk/core/step_kind.hpp"
#include "writer_parts.hpp"

namespace styk {

namespace {

// Abaqus data lines hold at most 16 entries.
constexpr int kEntriesPerLine = 16;

std::string num(double value) { return inp::shortest_number(value); }

void write_id_lines(std::ostream& out, const std::vector<int>& indices,
                    const std::vector<Id>& ids_by_index) {
  int on_line = 0;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    out << ids_by_index[indices[i]];
    const bool last = i + 1 == indices.size();
    if (last || ++on_line == kEntriesPerLine) {
      out << '\n';
      on_line = 0;
    } else {
      out << ", ";
    }
  }
}

void write_mesh(const Model& model, std::ostream& out) {
  out << "*NODE\n";
  for (int n = 0; n < model.node_count(); ++n) {
    const Vec3& x = model.coords[n];
    out << model.node_ids[n] << ", " << num(x[0]) << ", " << num(x[1]) << ", " << num(x[2]) << '\n';
  }
  std::string type;
  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    if (element.type != type) {
      type = element.type;
      out << "*ELEMENT, TYPE=" << type << '\n';
    }
    // Id plus up to 15 nodes on the first line, then 16 per continuation line.
    out << element.id;
    int on_line = 1;
    const int* nodes = model.element_nodes(e);
    for (int i = 0; i < element.node_count; ++i) {
      if (on_line == kEntriesPerLine) {
        out << ",\n";
        on_line = 0;
      } else {
        out << ", ";
      }
      out << model.node_ids[nodes[i]];
      ++on_line;
    }
    out << '\n';
  }
  std::vector<Id> element_ids;
  element_ids.reserve(model.elements.size());
  for (const Element& element : model.elements) element_ids.push_back(element.id);
  for (const auto& [name, set] : model.nsets) {
    out << "*NSET, NSET=" << name << '\n';
    write_id_lines(out, set.nodes, model.node_ids);
  }
  for (const auto& [name, set] : model.elsets) {
    out << "*ELSET, ELSET=" << name << '\n';
    write_id_lines(out, set.elements, element_ids);
  }
}

// Isotropic when the three diagonal values agree, TYPE=ORTHO otherwise.
void write_conductivity(std::ostream& out, const char* keyword,
                        const std::optional<std::array<double, 3>>& k) {
  if (!k) return;
  const auto& v = *k;
  if (v[0] == v[1] && v[1] == v[2])
    out << keyword << '\n' << num(v[0]) << '\n';
  else
    out << keyword << ", TYPE=ORTHO\n"
        << num(v[0]) << ", " << num(v[1]) << ", " << num(v[2]) << '\n';
}

// *BEAM SECTION as CalculiX reads it; INTEGRATION= only when the deck gave it (Styk-only:
// CalculiX warns "parameter not recognized" and goes on).
void write_beam_section(const Section& s, std::ostream& out) {
  const BeamSection& beam = *s.beam;
  out << "*BEAM SECTION, ELSET=" << s.elset << ", MATERIAL=" << s.material
      << ", SECTION=" << beam_shape_name(beam.shape);
  if (beam.integration_given)
    out << ", INTEGRATION=" << (beam.integration == BeamIntegration::Full ? "FULL" : "REDUCED");
  out << '\n';
  for (std::size_t k = 0; k < beam.dimensions.size(); ++k)
    out << (k > 0 ? ", " : "") << num(beam.dimensions[k]);
  out << '\n';
  if (beam.direction_given)
    out << num(beam.direction[0]) << ", " << num(beam.direction[1]) << ", "
        << num(beam.direction[2]) << '\n';
}

// *SHELL SECTION as CalculiX reads it (OFFSET only when not zero; the section points only when
// the deck gave them).
void write_shell_section(const Section& s, std::ostream& out) {
  out << "*SHELL SECTION, ELSET=" << s.elset << ", MATERIAL=" << s.material;
  if (s.shell->offset != 0.0) out << ", OFFSET=" << num(s.shell->offset);
  out << '\n' << num(s.thickness.value_or(0.0));
  if (s.shell->section_points_given) out << ", " << s.shell->section_points;
  out << '\n';
}

// *NORMAL lines, one per element and node, in the order read (a later line for the same element
// and node wins on reading back, as it did here).
void write_normals(const Model& model, std::ostream& out) {
  if (model.normals.empty()) return;
  out << "*NORMAL\n";
  for (const UserNormal& n : model.normals)
    out << model.elements[n.element].id << ", " << model.node_ids[n.node] << ", "
        << num(n.direction[0]) << ", " << num(n.direction[1]) << ", " << num(n.direction[2])
        << '\n';
}

void write_properties(const Model& model, std::ostream& out) {
  for (const Material& m : model.materials) {
    out << "*MATERIAL, NAME=" << m.name << '\n';
    inp::write_material_law(m, out);
    write_conductivity(out, "*CONDUCTIVITY", m.conductivity);
    write_conductivity(out, "*ELECTRICAL CONDUCTIVITY", m.electrical_conductivity);
  }
  for (const Section& s : model.sections) {
    if (s.beam) {
      write_beam_section(s, out);
      continue;
    }
    if (s.shell) {
      write_shell_section(s, out);
      continue;
    }
    out << "*SOLID SECTION, ELSET=" << s.elset << ", MATERIAL=" << s.material
        << (s.selective_volumetric ? ", TECHNIQUE=SELECTIVE" : "")
        << (s.orientation.empty() ? "" : ", ORIENTATION=" + s.orientation) << '\n';
    if (s.thickness) out << num(*s.thickness) << '\n';
  }
  write_normals(model, out);
}

void write_boundaries(const Model& model, const std::vector<Boundary>& boundaries, bool op_new,
                      std::ostream& out) {
  std::size_t plain = 0;  // *BOUNDARY, FIXED lines are written by write_step_changes
  for (const Boundary& b : boundaries) plain += b.fixed ? 0 : 1;
  if (plain == 0 && !op_new) return;
  out << "*BOUNDARY" << (op_new ? ", OP=NEW" : "") << '\n';
  for (const Boundary& b : boundaries)
    if (!b.fixed)
      out << model.node_ids[b.node] << ", " << b.dof << ", " << b.dof << ", " << num(b.value)
          << '\n';
}

const char* solver_name(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::Cholmod:
      return "SPOOLES";  // read back as the direct solver; CalculiX knows this name
    case LinearSolverKind::Iterative:
      return "ITERATIVE CHOLESKY";
    case LinearSolverKind::Automatic:
      break;
  }
  return nullptr;
}

const char* output_keyword(OutputRequest::Kind kind) {
  switch (kind) {
    case OutputRequest::Kind::NodePrint:
      return "*NODE PRINT";
    case OutputRequest::Kind::ElementPrint:
      return "*EL PRINT";
    case OutputRequest::Kind::NodeFile:
      return "*NODE FILE";
    case OutputRequest::Kind::ElementFile:
      return "*EL FILE";
    case OutputRequest::Kind::ContactPrint:
      return "*CONTACT PRINT";
    case OutputRequest::Kind::SectionPrint:
      return "*SECTION PRINT";
  }
  return "";
}

void write_step(const Model& model, const Step& step, std::ostream& out) {
  out << "*STEP";
  if (!step.name.empty()) out << ", NAME=" << step.name;
  out << '\n';
  if (step.has_procedure && step.kind != StepKind::Static) {
    const StaticProcedure& p = step.procedure;
    out << procedure_keyword(step.kind) << ", STEADY STATE\n"
        << num(p.initial_increment) << ", " << num(p.total_time) << '\n';
  } else if (step.has_procedure) {
    const StaticProcedure& p = step.procedure;
    out << "*STATIC";
    if (const char* solver = solver_name(p.solver)) out << ", SOLVER=" << solver;
    if (p.fixed_increments) out << ", DIRECT";
    out << '\n' << num(p.initial_increment) << ", " << num(p.total_time);
    if (p.min_increment || p.max_increment)
      out << ", " << (p.min_increment ? num(*p.min_increment) : "");
    if (p.max_increment) out << ", " << num(*p.max_increment);
    out << '\n';
  }
  write_boundaries(model, step.boundaries, step.boundary_op_new, out);
  inp::write_step_changes(model, step, out);
  if (!step.cloads.empty() || step.cload_op_new) {
    out << "*CLOAD" << (step.cload_op_new ? ", OP=NEW" : "") << '\n';
    for (const ConcentratedLoad& c : step.cloads)
      out << model.node_ids[c.node] << ", " << c.dof << ", " << num(c.value) << '\n';
  }
  if (!step.dloads.empty() || step.dload_op_new) {
    out << "*DLOAD" << (step.dload_op_new ? ", OP=NEW" : "") << '\n';
    for (const DistributedLoad& d : step.dloads)
      out << model.elements[d.element].id << ", P" << d.face << ", " << num(d.magnitude) << '\n';
  }
  inp::write_body_loads(model, step, out);
  inp::write_step_temperatures(model, step, out);
  inp::write_step_penetrations(model, step, out);
  if (!step.cfluxes.empty() || step.cflux_op_new) {
    out << (step.kind == StepKind::ElectricConduction ? "*CECUR" : "*CFLUX")
        << (step.cflux_op_new ? ", OP=NEW" : "") << '\n';
    for (const ConcentratedLoad& c : step.cfluxes)
      out << model.node_ids[c.node] << ", " << c.dof << ", " << num(c.value) << '\n';
  }
  if (!step.dfluxes.empty() || step.dflux_op_new) {
    out << "*DFLUX" << (step.dflux_op_new ? ", OP=NEW" : "") << '\n';
    for (const DistributedLoad& d : step.dfluxes)
      out << model.elements[d.element].id << ", S" << d.face << ", " << num(d.magnitude) << '\n';
  }
  for (const OutputRequest& o : step.outputs) {
    const bool nodal =
        o.kind == OutputRequest::Kind::NodePrint || o.kind == OutputRequest::Kind::NodeFile;
    out << output_keyword(o.kind);
    if (o.kind == OutputRequest::Kind::SectionPrint)
      out << ", SURFACE=" << o.set << ", NAME=" << o.name;
    else if (!o.set.empty())
      out << (nodal ? ", NSET=" : ", ELSET=") << o.set;
    if (o.totals) out << (o.totals_only ? ", TOTALS=ONLY" : ", TOTALS=YES");
    if (o.global) out << (*o.global ? ", GLOBAL=YES" : ", GLOBAL=NO");
    if (o.frequency)
      out << (o.kind == OutputRequest::Kind::SectionPrint ? ", FREQUENCYF=" : ", FREQUENCY=")
          << *o.frequency;
    if (o.position == OutputRequest::Position::Centroidal) out << ", POSITION=CENTROIDAL";
    if (o.position == OutputRequest::Position::AveragedAtNodes)
      out << ", POSITION=AVERAGED AT NODES";
    out << '\n';
    for (std::size_t i = 0; i < o.vars.size(); ++i) out << (i ? ", " : "") << o.vars[i];
    out << '\n';
  }
  out << "*END STEP\n";
}

}  // namespace

void write_inp(const Model& model, std::ostream& out) {
  out << "** Written by Styk" << (model.source.empty() ? "" : " from " + model.source) << '\n';
  if (!model.heading.empty()) out << "*HEADING\n" << model.heading << '\n';
  write_mesh(model, out);
  write_properties(model, out);
  inp::write_contact_and_constraints(model, out);
  inp::write_ties_and_couplings(model, out);
  write_boundaries(model, model.boundaries, false, out);
  for (const Step& step : model.steps) write_step(model, step, out);
}

}  // namespace styk
