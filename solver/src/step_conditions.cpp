#include "step_conditions.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "coupling_loads.hpp"
#include "node_rotations.hpp"

namespace styk::solver_detail {
namespace {

int checked_dof(const Model& model, const PreparedModel& prepared, int node, int dof,
                const SourceLoc& where, const char* what) {
  if (node < 0 || node >= model.node_count())
    throw InputError(where, std::string(what) + " on an undefined node");
  if (dof < 1 || dof > kMaxNodeDofs)
    throw InputError(where, std::string(what) + " on degree of freedom " + std::to_string(dof) +
                                " of node " + std::to_string(model.node_ids[node]) +
                                ": nodes have the displacements 1, 2, 3 and, at beam nodes, the "
                                "rotations 4, 5, 6");
  const int active = prepared.active_of_node[node];
  if (active < 0)
    throw InputError(where, std::string(what) + " on node " + std::to_string(model.node_ids[node]) +
                                ", which belongs to no element (it has no stiffness)");
  const int index = prepared.dof(active, dof - 1);
  if (index < 0)
    throw InputError(where, std::string(what) + " on degree of freedom " + std::to_string(dof) +
                                " of node " + std::to_string(model.node_ids[node]) +
                                ", which carries no rotations: its elements have the "
                                "displacements 1, 2, 3 only (rotations 4, 5, 6 exist at nodes of "
                                "beam elements)");
  return index;
}

// "z" or "x, z" or "rx, ry": the global directions no element at active node a stiffens (the
// part of `offset` 0 = translations, 3 = rotations).
std::string unstiffened_directions(const PreparedModel& prepared, int a, int offset) {
  static const char* const kAxis[] = {"x", "y", "z", "rx", "ry", "rz"};
  std::string list;
  for (int d = 0; d < 3; ++d)
    if (prepared.inactive_dof(prepared.dof(a, offset + d)))
      list += (list.empty() ? "" : ", ") + std::string(kAxis[offset + d]);
  return list;
}

// Per active dof, 1 when it is inactive in the nodal system (the node's *TRANSFORM axes where it
// has one): no element stiffens that direction. A transformed node must keep its inactive global
// directions as local axes (e.g. a cylindrical system about z for plane elements), otherwise its
// local dofs would mix stiffened and unstiffened directions.
std::vector<char> inactive_nodal_dofs(const Model& model, const PreparedModel& prepared) {
  std::vector<char> inactive(prepared.active_dofs(), 0);
  bool any = false;
  for (int dof = 0; dof < prepared.active_dofs(); ++dof)
    if (prepared.inactive_dof(dof)) {
      inactive[dof] = 1;
      any = true;
    }
  if (!any || model.transforms.empty()) return inactive;
  for (const Transform& transform : model.transforms) {  // a later *TRANSFORM overrides
    const NodeSet* set = model.find_nset(transform.nset);
    if (set == nullptr) continue;  // NodeRotations reports it
    for (int node : set->nodes) {
      const int a = prepared.active_of_node[node];
      if (a < 0) continue;
      Eigen::Matrix3d R;
      if (!local_axes_at(transform.axes, model.coords[node], R)) continue;  // reported elsewhere
      // Translations and rotations turn alike (node_rotations.hpp): each triple separately.
      for (int offset = 0; offset < prepared.node_dofs(a); offset += 3) {
        const int first = prepared.dof(a, offset);
        int global_inactive = 0, local_inactive = 0;
        for (int d = 0; d < 3; ++d) {
          global_inactive += prepared.inactive_dof(first + d) ? 1 : 0;
          double stiffened_part = 0.0;  // the local axis' components along stiffened directions
          for (int g = 0; g < 3; ++g)
            if (!prepared.inactive_dof(first + g)) stiffened_part += R(g, d) * R(g, d);
          inactive[first + d] = stiffened_part < 1e-18 ? 1 : 0;
          local_inactive += inactive[first + d];
        }
        if (local_inactive != global_inactive)
          throw InputError(transform.where,
                           "*TRANSFORM: node " + std::to_string(model.node_ids[node]) +
                               " belongs only to elements without stiffness along " +
                               unstiffened_directions(prepared, a, offset) +
                               " (plane elements, planar beams), so its local system must keep "
                               "that direction as one of its axes (e.g. a cylindrical system "
                               "about z)");
      }
    }
  }
  return inactive;
}

bool is_reference_node(const std::vector<DistributingTransfer>& transfers, int node) {
  for (const DistributingTransfer& t : transfers)
    if (t.reference_node == node) return true;
  return false;
}

// `loads` plus the forces carried from distributing couplings' reference nodes (global; a
// surface node with a *TRANSFORM is refused).
std::map<int, double> with_distributed(const Model& model, const PreparedModel& prepared,
                                       std::map<int, double> loads,
                                       const std::map<int, Eigen::Vector3d>& carried) {
  for (const auto& [node, force] : carried) {
    for (const Transform& t : model.transforms)
      if (const NodeSet* set = model.find_nset(t.nset);
          set && std::binary_search(set->nodes.begin(), set->nodes.end(), node))
        throw InputError(t.where, "node " + std::to_string(model.node_ids[node]) +
                                      " of a distributing coupling's surface has a *TRANSFORM, "
                                      "which Styk does not combine with the carried loads");
    for (int d = 0; d < 3; ++d)
      loads[checked_dof(model, prepared, node, d + 1, {}, "distributed coupling load")] += force[d];
  }
  return loads;
}

std::vector<DofValue> to_vector(const std::map<int, double>& values) {
  std::vector<DofValue> out;
  out.reserve(values.size());
  for (const auto& [dof, value] : values) out.push_back({dof, value});
  return out;
}

}  // namespace

std::vector<StepConditions> accumulate_step_conditions(const Model& model,
                                                       const PreparedModel& prepared) {
  const std::vector<char> inactive = inactive_nodal_dofs(model, prepared);
  // A dof no element stiffens takes no load and no displacement but zero; a zero boundary value
  // is accepted silently (CalculiX decks of plane models often fix dof 3).
  auto refuse_inactive = [&](int dof, const SourceLoc& where, const std::string& what) {
    const int node = prepared.node_of_active[prepared.node_of(dof)];
    throw InputError(where,
                     what + " on degree of freedom " + std::to_string(prepared.component(dof) + 1) +
                         " of node " + std::to_string(model.node_ids[node]) +
                         ", which no element there stiffens (plane elements carry only "
                         "ux and uy, planar beams ux, uy and rz)" +
                         (what == "boundary condition" ? "; only a zero value is accepted" : ""));
  };
  std::map<int, bool> fixed;  // per prescribed dof of the steps: held by *BOUNDARY, FIXED
  auto prescribe = [&](std::map<int, double>& into, const Boundary& b) {
    const int dof = checked_dof(model, prepared, b.node, b.dof, b.where, "boundary condition");
    if (inactive[dof] && b.value != 0.0) refuse_inactive(dof, b.where, "boundary condition");
    into[dof] = b.value;
    fixed[dof] = b.fixed;
  };
  std::map<int, double> model_level;
  for (int dof = 0; dof < prepared.active_dofs(); ++dof)
    if (inactive[dof]) model_level[dof] = 0.0;
  for (const Boundary& b : model.boundaries) prescribe(model_level, b);

  std::map<int, double> prescribed = model_level;
  std::map<int, double> nodal_loads;
  // Loads on the reference nodes of distributing couplings, carried to their surfaces.
  const std::vector<DistributingTransfer> transfers = distributing_transfers(model, prepared);
  std::map<std::pair<int, int>, std::pair<double, SourceLoc>> reference_loads;
  std::map<std::pair<int, int>, DistributedLoad> pressures;
  std::map<std::pair<int, Vec3>, BodyLoad> body_loads;  // (element, gravity direction or none)
  std::vector<StepConditions> out;
  out.reserve(model.steps.size());
  for (const Step& step : model.steps) {
    if (step.boundary_op_new) {
      prescribed = model_level;
      fixed.clear();
    }
    if (step.cload_op_new) {
      nodal_loads.clear();
      reference_loads.clear();
    }
    if (step.dload_op_new) {
      pressures.clear();
      body_loads.clear();
    }
    for (const Boundary& b : step.boundaries) prescribe(prescribed, b);
    for (const ConcentratedLoad& c : step.cloads) {
      if (is_reference_node(transfers, c.node)) {
        reference_loads[{c.node, c.dof}] = {c.value, c.where};
        continue;
      }
      const int dof = checked_dof(model, prepared, c.node, c.dof, c.where, "concentrated load");
      if (inactive[dof]) refuse_inactive(dof, c.where, "concentrated load");
      nodal_loads[dof] = c.value;
    }
    for (const DistributedLoad& d : step.dloads) {
      if (d.element < 0 || d.element >= model.element_count())
        throw InputError(d.where, "distributed load on an undefined element");
      const TElement& element = *prepared.formulation[d.element];
      const int labels = element.distributed_load_labels();
      if (d.face < 1 || d.face > labels)
        throw InputError(
            d.where, "element " + std::to_string(model.elements[d.element].id) + " (" +
                         model.elements[d.element].type + ") takes the load labels " +
                         (labels == 0 ? std::string("none") : "P1..P" + std::to_string(labels)) +
                         (element.faces().empty() ? "" : " (its faces)") + ", not P" +
                         std::to_string(d.face));
      pressures[{d.element, d.face}] = d;
    }
    for (const BodyLoad& b : step.body_loads) {
      if (b.element < 0 || b.element >= model.element_count())
        throw InputError(b.where, "body load on an undefined element");
      const Vec3 key = b.kind == BodyLoad::Kind::Gravity ? b.direction : Vec3{0.0, 0.0, 0.0};
      body_loads[{b.element, key}] = b;
    }
    StepConditions conditions;
    conditions.prescribed = to_vector(prescribed);
    for (const auto& [dof, held] : fixed)
      if (held && prescribed.count(dof) != 0) conditions.fixed.push_back(dof);
    conditions.nodal_loads = to_vector(with_distributed(
        model, prepared, nodal_loads, distribute_reference_loads(transfers, reference_loads)));
    for (const auto& entry : pressures) conditions.pressures.push_back(entry.second);
    for (const auto& entry : body_loads) conditions.body_loads.push_back(entry.second);
    out.push_back(std::move(conditions));
  }
  return out;
}

std::vector<int> prescribed_dofs(const StepConditions& conditions) {
  std::vector<int> dofs;
  dofs.reserve(conditions.prescribed.size());
  for (const DofValue& p : conditions.prescribed) dofs.push_back(p.dof);
  return dofs;
}

}  // namespace styk::solver_detail
