// Ties, couplings, MPCs, pre-tension sections and initial stresses of a written deck, and the
// step data they bring: *DLOAD GRAV / CENTRIF, *CHANGE SOLID SECTION and *BOUNDARY, FIXED.
#include "writer_parts.hpp"

namespace styk::inp {

namespace {

std::string num(double value) { return shortest_number(value); }

const char* mpc_type(Mpc::Type type) {
  switch (type) {
    case Mpc::Type::Beam:
      return "BEAM";
    case Mpc::Type::Straight:
      return "STRAIGHT";
    case Mpc::Type::Plane:
      return "PLANE";
  }
  return "BEAM";
}

// "first, last" lines for a sorted dof list (consecutive dofs joined).
void write_dof_ranges(const std::vector<int>& dofs, std::ostream& out) {
  for (std::size_t i = 0; i < dofs.size();) {
    std::size_t j = i;
    while (j + 1 < dofs.size() && dofs[j + 1] == dofs[j] + 1) ++j;
    out << dofs[i] << ", " << dofs[j] << '\n';
    i = j + 1;
  }
}

}  // namespace

void write_ties_and_couplings(const Model& model, std::ostream& out) {
  for (const Tie& tie : model.ties) {
    out << "*TIE, NAME=" << tie.name;
    if (tie.position_tolerance) out << ", POSITION TOLERANCE=" << num(*tie.position_tolerance);
    if (!tie.adjust) out << ", ADJUST=NO";
    out << '\n' << tie.slave << ", " << tie.master << '\n';
  }
  for (const Coupling& c : model.couplings) {
    out << "*COUPLING, REF NODE=" << model.node_ids[c.reference_node] << ", SURFACE=" << c.surface
        << ", CONSTRAINT NAME=" << c.name;
    if (!c.orientation.empty()) out << ", ORIENTATION=" << c.orientation;
    out << '\n' << (c.kind == Coupling::Kind::Kinematic ? "*KINEMATIC" : "*DISTRIBUTING") << '\n';
    write_dof_ranges(c.dofs, out);
  }
  for (const Mpc& mpc : model.mpcs) {
    out << "*MPC\n" << mpc_type(mpc.type);
    // At most 15 nodes after the type on the first line, 16 on the following ones.
    std::size_t on_line = 1;
    for (int node : mpc.nodes) {
      if (on_line == 16) {
        out << '\n';
        on_line = 0;
      } else {
        out << ", ";
      }
      out << model.node_ids[node];
      ++on_line;
    }
    out << '\n';
  }
  for (const PretensionSection& p : model.pretension_sections) {
    out << "*PRE-TENSION SECTION, SURFACE=" << p.surface
        << ", NODE=" << model.node_ids[p.reference_node] << '\n';
    if (p.normal)
      out << num((*p.normal)[0]) << ", " << num((*p.normal)[1]) << ", " << num((*p.normal)[2])
          << '\n';
  }
  if (!model.initial_stresses.empty()) {
    out << "*INITIAL CONDITIONS, TYPE=STRESS\n";
    for (const InitialStress& s : model.initial_stresses) {
      out << model.elements[s.element].id << ", " << s.point;
      for (double c : s.stress) out << ", " << num(c);
      out << '\n';
    }
  }
}

void write_step_changes(const Model& model, const Step& step, std::ostream& out) {
  for (const SectionChange& change : step.section_changes)
    out << "*CHANGE SOLID SECTION, ELSET=" << change.elset << ", MATERIAL=" << change.material
        << '\n';
  std::vector<const Boundary*> fixed;
  for (const Boundary& b : step.boundaries)
    if (b.fixed) fixed.push_back(&b);
  if (!fixed.empty()) {
    out << "*BOUNDARY, FIXED\n";
    for (const Boundary* b : fixed)
      out << model.node_ids[b->node] << ", " << b->dof << ", " << b->dof << '\n';
  }
}

void write_body_loads(const Model& model, const Step& step, std::ostream& out) {
  if (step.body_loads.empty()) return;
  out << "*DLOAD\n";
  for (const BodyLoad& b : step.body_loads) {
    out << model.elements[b.element].id;
    if (b.kind == BodyLoad::Kind::Gravity)
      out << ", GRAV, " << num(b.magnitude);
    else
      out << ", CENTRIF, " << num(b.magnitude) << ", " << num(b.point[0]) << ", " << num(b.point[1])
          << ", " << num(b.point[2]);
    out << ", " << num(b.direction[0]) << ", " << num(b.direction[1]) << ", " << num(b.direction[2])
        << '\n';
  }
}

}  // namespace styk::inp
