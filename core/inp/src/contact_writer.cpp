// Writing of the contact, local-system, constraint and temperature keywords (writer_parts.hpp).
#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "writer_parts.hpp"

namespace styk::inp {

namespace {

// Abaqus *EQUATION lines hold at most four terms.
constexpr std::size_t kTermsPerLine = 4;

void write_axes(const LocalAxes& axes, std::ostream& out) {
  const auto& n = shortest_number;
  out << n(axes.a[0]) << ", " << n(axes.a[1]) << ", " << n(axes.a[2]) << ", " << n(axes.b[0])
      << ", " << n(axes.b[1]) << ", " << n(axes.b[2]) << '\n';
}

void write_surfaces(const Model& model, std::ostream& out) {
  for (const auto& [name, surface] : model.surfaces) {
    const bool nodes = surface.kind == Surface::Kind::Nodes;
    out << "*SURFACE, NAME=" << name << ", TYPE=" << (nodes ? "NODE" : "ELEMENT") << '\n';
    for (int n : surface.nodes) out << model.node_ids[n] << '\n';
    for (const SurfaceFace& f : surface.faces)
      out << model.elements[f.element].id << ", S" << f.face << '\n';
  }
}

void write_behavior(const PressureOverclosure& b, std::ostream& out) {
  const auto& n = shortest_number;
  out << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=";
  switch (b.law) {
    case PressureOverclosure::Law::Hard:
      out << "HARD\n";
      return;
    case PressureOverclosure::Law::Linear:
      out << "LINEAR\n" << n(b.slope);
      // CalculiX reads the fields by position: an empty sigma_inf keeps c0 in the third field.
      if (b.sigma_inf || b.c0) out << ", " << (b.sigma_inf ? n(*b.sigma_inf) : std::string());
      if (b.c0) out << ", " << n(*b.c0);
      out << '\n';
      return;
    case PressureOverclosure::Law::Exponential:
      out << "EXPONENTIAL\n" << n(b.c0.value_or(0.0)) << ", " << n(b.p0) << '\n';
      return;
    case PressureOverclosure::Law::Tied:
      out << "TIED\n" << n(b.slope) << '\n';
      return;
  }
}

void write_interactions(const std::map<std::string, SurfaceInteraction>& interactions,
                        std::ostream& out) {
  for (const auto& [name, interaction] : interactions) {
    out << "*SURFACE INTERACTION, NAME=" << name << '\n';
    write_behavior(interaction.behavior, out);
    if (!interaction.friction) continue;
    const Friction& f = *interaction.friction;
    switch (f.kind) {
      case Friction::Kind::Rough:
        out << "*FRICTION, ROUGH\n";
        break;
      case Friction::Kind::Anisotropic:
        out << "*FRICTION, ANISOTROPIC, ORIENTATION=" << f.orientation << '\n'
            << shortest_number(f.mu) << ", " << shortest_number(f.mu2) << '\n';
        break;
      case Friction::Kind::Isotropic:
        out << "*FRICTION\n" << shortest_number(f.mu);
        if (f.stick_slope) out << ", " << shortest_number(*f.stick_slope);
        out << '\n';
        break;
    }
  }
}

const char* type_name(ContactPair::Type type) {
  switch (type) {
    case ContactPair::Type::SurfaceToSurface:
      return "SURFACE TO SURFACE";
    case ContactPair::Type::Mortar:
      return "MORTAR";
    case ContactPair::Type::NodeToSurface:
      break;
  }
  return "NODE TO SURFACE";
}

void write_contact_pairs(const std::vector<ContactPair>& pairs, std::ostream& out) {
  for (const ContactPair& pair : pairs) {
    out << "*CONTACT PAIR, INTERACTION=" << pair.interaction << ", TYPE=" << type_name(pair.type);
    if (!pair.adjust_nset.empty()) out << ", ADJUST=" << pair.adjust_nset;
    if (pair.adjust_tolerance) out << ", ADJUST=" << shortest_number(*pair.adjust_tolerance);
    out << '\n' << pair.slave << ", " << pair.master << '\n';
    if (pair.clearance)
      out << "*CLEARANCE, SLAVE=" << pair.slave << ", MASTER=" << pair.master
          << ", VALUE=" << shortest_number(*pair.clearance) << '\n';
  }
}

void write_equations(const Model& model, std::ostream& out) {
  if (model.equations.empty()) return;
  out << "*EQUATION\n";
  for (const Equation& equation : model.equations) {
    out << equation.terms.size() << '\n';
    for (std::size_t i = 0; i < equation.terms.size(); ++i) {
      const EquationTerm& t = equation.terms[i];
      out << model.node_ids[t.node] << ", " << t.dof << ", " << shortest_number(t.coefficient);
      const bool line_ends = (i + 1) % kTermsPerLine == 0 || i + 1 == equation.terms.size();
      out << (line_ends ? "\n" : ", ");
    }
  }
}

void write_temperatures(const Model& model, const std::vector<NodalTemperature>& temperatures,
                        std::ostream& out) {
  for (const NodalTemperature& t : temperatures)
    out << model.node_ids[t.node] << ", " << shortest_number(t.value) << '\n';
}

}  // namespace

std::string shortest_number(double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  if (result.ptr - buf <= kMaxFieldChars) return std::string(buf, result.ptr);
  // CalculiX reads at most 20 characters per field and refuses a longer number: write the most
  // significant digits that fit (13 at least, for e-100 and beyond; a rounding of 5e-14 or less).
  for (int digits = 16; digits > 0; --digits) {
    const auto r =
        std::to_chars(buf, buf + sizeof buf, value, std::chars_format::scientific, digits);
    if (r.ptr - buf <= kMaxFieldChars) return std::string(buf, r.ptr);
  }
  return std::string(buf, result.ptr);  // not reached: 1 digit always fits
}

void write_contact_and_constraints(const Model& model, std::ostream& out) {
  for (const auto& [name, orientation] : model.orientations) {
    const bool cylindrical = orientation.axes.system == CoordinateSystem::Cylindrical;
    out << "*ORIENTATION, NAME=" << name
        << ", SYSTEM=" << (cylindrical ? "CYLINDRICAL" : "RECTANGULAR") << '\n';
    write_axes(orientation.axes, out);
  }
  write_surfaces(model, out);
  write_interactions(model.surface_interactions, out);
  write_contact_pairs(model.contact_pairs, out);
  for (const Transform& transform : model.transforms) {
    const bool cylindrical = transform.axes.system == CoordinateSystem::Cylindrical;
    out << "*TRANSFORM, NSET=" << transform.nset << ", TYPE=" << (cylindrical ? "C" : "R") << '\n';
    write_axes(transform.axes, out);
  }
  write_equations(model, out);
  for (const CyclicSymmetry& c : model.cyclic_symmetries) {
    out << "*TIE, NAME=" << c.tie << ", CYCLIC SYMMETRY";
    if (c.position_tolerance)
      out << ", POSITION TOLERANCE=" << shortest_number(*c.position_tolerance);
    out << '\n' << c.slave << ", " << c.master << '\n';
    out << "*CYCLIC SYMMETRY MODEL, N=" << c.sectors << ", NGRAPH=" << c.ngraph << ", TIE=" << c.tie
        << '\n';
    write_axes(LocalAxes{CoordinateSystem::Cylindrical, c.a, c.b}, out);
  }
  if (!model.initial_temperatures.empty()) {
    out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n";
    write_temperatures(model, model.initial_temperatures, out);
  }
}

void write_step_penetrations(const Model& model, const Step& step, std::ostream& out) {
  if (step.penetration_op_new && step.penetrations.empty())
    throw std::logic_error(
        "write_inp: *PRESSURE PENETRATION, OP=NEW needs a definition in the same step");
  for (std::size_t k = 0; k < step.penetrations.size(); ++k) {
    const PressurePenetration& pp = step.penetrations[k];
    out << "*PRESSURE PENETRATION, SLAVE=" << pp.slave << ", MASTER=" << pp.master;
    if (k == 0 && step.penetration_op_new) out << ", OP=NEW";
    if (!pp.leak_nset.empty()) out << ", LEAK=" << pp.leak_nset;
    out << '\n';
    // One line per exposed node; the shorter list repeats its first node (the lines' union is
    // what is read back).
    const std::size_t lines = std::max(pp.exposed_slave.size(), pp.exposed_master.size());
    for (std::size_t i = 0; i < lines; ++i) {
      const int s = pp.exposed_slave[i < pp.exposed_slave.size() ? i : 0];
      const int m = pp.exposed_master[i < pp.exposed_master.size() ? i : 0];
      out << model.node_ids[s] << ", " << model.node_ids[m] << ", " << shortest_number(pp.pressure)
          << ", " << shortest_number(pp.critical) << '\n';
    }
  }
}

void write_step_temperatures(const Model& model, const Step& step, std::ostream& out) {
  if (step.temperatures.empty() && !step.temperature_op_new) return;
  out << "*TEMPERATURE" << (step.temperature_op_new ? ", OP=NEW" : "") << '\n';
  write_temperatures(model, step.temperatures, out);
}

}  // namespace styk::inp
