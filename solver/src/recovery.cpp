#include "recovery.hpp"

#include <optional>

#include "assembly.hpp"
#include "parallel.hpp"

#include "thermal_load.hpp"

namespace styk::solver_detail {
namespace {

// Scratch of one worker, sized on first use and reused for every element.
struct RecoveryScratch {
  ElementGeometry geometry;
  Eigen::VectorXd ue, dv;
  Eigen::MatrixXd strain, stress, forces, moments, positions;
  std::vector<MaterialPoint> laws;
  std::vector<int> dofs;
};

bool has_shells(const PreparedModel& prepared) {
  for (const TElement* element : prepared.formulation)
    if (element->section_measure() == SectionMeasure::Shell) return true;
  return false;
}

// Nodal displacements and rotations (global components) from the solution on the active dofs.
void nodal_motions(const Model& model, const PreparedModel& prepared, const std::vector<double>& u,
                   IncrementResult& out) {
  out.U.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  if (prepared.has_rotations()) out.UR.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  for (int a = 0; a < prepared.active_nodes(); ++a) {
    const int first = prepared.dof_offset[a];
    const int node = prepared.node_of_active[a];
    out.U[node] = {u[first], u[first + 1], u[first + 2]};
    if (prepared.node_dofs(a) == kMaxNodeDofs)
      out.UR[node] = {u[first + 3], u[first + 4], u[first + 5]};
  }
}

// ENER, THE, the element's volume and internal energy from the stresses and strains just
// recovered (s.stress, s.strain): ENER = 1/2 (sigma + sigma0) : (eps - eps_th), the energy
// density of a linear law from the unstrained state, its integral the element's energy.
void element_energies(const TElement& element, const ElementGeometry& g, const ElementMaterial& law,
                      RuleKind kind, const Eigen::MatrixXd* sigma0, int e, int first,
                      RecoveryScratch& s, IncrementResult& out) {
  element.point_laws(g, law, kind, s.laws);
  element.point_volumes(g, kind, s.dv);
  for (int p = 0; p < s.stress.rows(); ++p) {
    Tensor6 thermal{};
    for (int c = 0; c < 6; ++c) thermal[c] = s.laws[p].thermal_strain[c] * (c < 3 ? 1.0 : 0.5);
    if (!out.THE.empty()) out.THE[first + p] = thermal;
    if (out.ENER.empty()) continue;
    double energy = 0.0;
    for (int c = 0; c < 6; ++c) {
      const double stress = s.stress(p, c) + (sigma0 ? (*sigma0)(p, c) : 0.0);
      energy += (c < 3 ? 0.5 : 1.0) * stress * (s.strain(p, c) - thermal[c]);
    }
    out.ENER[first + p] = energy;
    out.element_energy[e] += energy * s.dv(p);
    out.element_volume[e] += s.dv(p);
  }
}

}  // namespace

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const RecoveryInput& input, int threads, IncrementResult& out) {
  threads = resolve_threads(threads);
  const std::vector<double>& u = input.u;
  const std::optional<ElementStates> initial_states =
      input.states ? std::nullopt
                   : std::optional<ElementStates>(std::in_place, model, prepared, 0, nullptr);
  const ElementStates& states = input.states ? *input.states : *initial_states;
  nodal_motions(model, prepared, u, out);
  out.RF.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  if (prepared.has_rotations()) out.RM.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  out.ip_offset = prepared.ip_offset;
  out.S.assign(prepared.ip_offset.back(), Tensor6{});
  out.E.assign(prepared.ip_offset.back(), Tensor6{});
  const int stations = prepared.station_offset.back();
  if (stations > 0) {  // structural elements: section forces and moments at their stations
    out.station_offset = prepared.station_offset;
    out.SF.assign(stations, Vec3{0.0, 0.0, 0.0});
    out.SM.assign(stations, Vec3{0.0, 0.0, 0.0});
    if (has_shells(prepared)) out.SFQ.assign(stations, {0.0, 0.0});
  }
  if (input.energies) {
    out.ENER.assign(prepared.ip_offset.back(), 0.0);
    out.element_volume.assign(model.element_count(), 0.0);
    out.element_energy.assign(model.element_count(), 0.0);
  }
  if (input.thermal_strains) out.THE.assign(prepared.ip_offset.back(), Tensor6{});
  bool cylindrical = false;  // some material axes depend on the point: keep the positions
  for (const Section& section : model.sections)
    if (const auto o = model.orientations.find(section.orientation); o != model.orientations.end())
      cylindrical = cylindrical || o->second.axes.system == CoordinateSystem::Cylindrical;
  if (cylindrical) out.ip_position.assign(prepared.ip_offset.back(), Vec3{});

  // Compact storage of the nodes with a constrained dof (only elements touching one need the
  // internal force): reaction node r keeps its dofs at internal[reaction_first[r] ...].
  std::vector<int> reaction_node(prepared.active_nodes(), -1);
  std::vector<int> node_of_reaction, reaction_first;
  int reaction_dofs = 0;
  for (int dof : input.reaction_dofs) {
    const int a = prepared.node_of(dof);
    if (reaction_node[a] >= 0) continue;
    reaction_node[a] = static_cast<int>(node_of_reaction.size());
    node_of_reaction.push_back(a);
    reaction_first.push_back(reaction_dofs);
    reaction_dofs += prepared.node_dofs(a);
  }

  std::vector<RecoveryScratch> scratch(threads);
  // The internal force of each element touching a reaction node, summed afterwards in element
  // order: per-thread sums would depend on which thread took which elements, and RF with them.
  std::vector<Eigen::VectorXd> element_force(model.element_count());
  parallel_for(model.element_count(), threads, 16, [&](int begin, int end, int worker) {
    RecoveryScratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      const int n = model.elements[e].node_count;
      const int* nodes = model.element_nodes(e);
      element_geometry(model, prepared, e, s.geometry);
      prepared.element_dofs(model, e, s.dofs);
      s.ue.resize(static_cast<Eigen::Index>(s.dofs.size()));
      for (std::size_t i = 0; i < s.dofs.size(); ++i)
        s.ue(static_cast<Eigen::Index>(i)) = u[s.dofs[i]];
      bool touches_reaction = false;
      for (int k = 0; k < n; ++k)
        touches_reaction =
            touches_reaction || reaction_node[prepared.active_of_node[nodes[k]]] >= 0;
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      const ElementMaterial law = states.law(e);
      const Eigen::MatrixXd* sigma0 = states.initial_stress(e);
      element.strains_stresses(s.geometry, law, prepared.rule_kind[e], s.ue, s.strain, s.stress,
                               options, sigma0);
      const int first = prepared.ip_offset[e];
      for (int p = 0; p < s.stress.rows(); ++p)
        for (int c = 0; c < 6; ++c) {
          out.S[first + p][c] = s.stress(p, c);
          out.E[first + p][c] = s.strain(p, c);
        }
      if (prepared.station_offset[e + 1] > prepared.station_offset[e]) {
        element.section_resultants(s.geometry, law, prepared.rule_kind[e], s.ue, s.forces,
                                   s.moments);
        const int station = prepared.station_offset[e];
        for (int k = 0; k < s.forces.rows(); ++k)
          for (int c = 0; c < 3; ++c) {
            out.SF[station + k][c] = s.forces(k, c);
            out.SM[station + k][c] = s.moments(k, c);
          }
        if (!out.SFQ.empty() && s.forces.cols() >= 5)  // shells: Q13, Q23 in columns 4 and 5
          for (int k = 0; k < s.forces.rows(); ++k)
            out.SFQ[station + k] = {s.forces(k, 3), s.forces(k, 4)};
      }
      // Beams have no 3D energy density at their fibre points (prepare_model refuses ENER, ELSE,
      // EVOL and THE requests in models with beams).
      const bool continuum = element.section_measure() != SectionMeasure::Beam &&
                             element.section_measure() != SectionMeasure::Shell;
      if (continuum && (input.energies || input.thermal_strains))
        element_energies(element, s.geometry, law, prepared.rule_kind[e], sigma0, e, first, s, out);
      if (!out.ip_position.empty()) {
        element.point_positions(s.geometry, prepared.rule_kind[e], s.positions);
        for (int p = 0; p < s.positions.rows(); ++p)
          out.ip_position[first + p] = {s.positions(p, 0), s.positions(p, 1), s.positions(p, 2)};
      }
      if (!touches_reaction) continue;

      // Internal force of the element (B-bar, incompatible modes, hourglass forces and the
      // thermal strain included).
      element.internal_force(s.geometry, law, prepared.rule_kind[e], s.ue, element_force[e],
                             options, sigma0);
    }
  });
  std::vector<double> internal(reaction_dofs, 0.0);
  for (int e = 0; e < model.element_count(); ++e) {
    if (element_force[e].size() == 0) continue;
    const int n = model.elements[e].node_count;
    const int m = prepared.formulation[e]->node_dofs();
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < n; ++k) {
      const int r = reaction_node[prepared.active_of_node[nodes[k]]];
      if (r < 0) continue;
      for (int c = 0; c < m; ++c) internal[reaction_first[r] + c] += element_force[e](m * k + c);
    }
  }

  // Constraint force in the nodal system, kept on the constrained dofs, reported globally: the
  // force part as RF, the moment part (nodes with rotations) as RM; a *TRANSFORM turns both.
  std::vector<char> constrained(prepared.active_dofs(), 0);
  for (int dof : input.reaction_dofs) constrained[dof] = 1;
  for (std::size_t r = 0; r < node_of_reaction.size(); ++r) {
    const int a = node_of_reaction[r];
    const int first = prepared.dof_offset[a];
    const Eigen::Matrix3d* R = input.rotations != nullptr ? input.rotations->of(a) : nullptr;
    for (int part = 0; part * 3 < prepared.node_dofs(a); ++part) {
      Eigen::Vector3d node_force;
      for (int d = 0; d < 3; ++d) node_force[d] = internal[reaction_first[r] + 3 * part + d];
      if (R != nullptr) node_force = R->transpose() * node_force;
      Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
      for (int d = 0; d < 3; ++d) {
        const int dof = first + 3 * part + d;
        if (constrained[dof]) reaction[d] = node_force[d] - input.f[dof];
      }
      if (R != nullptr) reaction = *R * reaction;
      Vec3& target = (part == 0 ? out.RF : out.RM)[prepared.node_of_active[a]];
      target = {reaction[0], reaction[1], reaction[2]};
    }
  }
}

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out) {
  recover_increment(model, prepared, RecoveryInput{prescribed, u, f}, threads, out);
}

}  // namespace styk::solver_detail
