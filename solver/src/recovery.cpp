#include "recovery.hpp"

#include "assembly.hpp"
#include "parallel.hpp"
#include "thermal_load.hpp"

namespace styk::solver_detail {
namespace {

// Scratch of one worker, sized on first use and reused for every element.
struct RecoveryScratch {
  ElementGeometry geometry;
  Eigen::VectorXd ue, fe, dT;
  Eigen::MatrixXd strain, stress, forces, moments;
  std::vector<int> dofs;
  std::vector<double> internal;  // internal force (global) on the dofs of the reaction nodes
};

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

}  // namespace

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const RecoveryInput& input, int threads, IncrementResult& out) {
  threads = resolve_threads(threads);
  const std::vector<double>& u = input.u;
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
  }

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
  for (RecoveryScratch& s : scratch) s.internal.assign(reaction_dofs, 0.0);
  parallel_for(model.element_count(), threads, 16, [&](int begin, int end, int worker) {
    RecoveryScratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      const int n = model.elements[e].node_count;
      const int m = element.node_dofs();
      const int* nodes = model.element_nodes(e);
      element_geometry(model, e, s.geometry);
      prepared.element_dofs(model, e, s.dofs);
      s.ue.resize(static_cast<Eigen::Index>(s.dofs.size()));
      for (std::size_t i = 0; i < s.dofs.size(); ++i)
        s.ue(static_cast<Eigen::Index>(i)) = u[s.dofs[i]];
      bool touches_reaction = false;
      for (int k = 0; k < n; ++k)
        touches_reaction =
            touches_reaction || reaction_node[prepared.active_of_node[nodes[k]]] >= 0;
      const Eigen::VectorXd* dT = nullptr;
      if (input.nodal_dT != nullptr) {
        element_temperature_changes(model, e, *input.nodal_dT, s.dT);
        if (!s.dT.isZero(0.0)) dT = &s.dT;
      }
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      element.strains_stresses(s.geometry, *prepared.material[e], prepared.rule_kind[e], s.ue,
                               s.strain, s.stress, options, dT);
      const int first = prepared.ip_offset[e];
      for (int p = 0; p < s.stress.rows(); ++p)
        for (int c = 0; c < 6; ++c) {
          out.S[first + p][c] = s.stress(p, c);
          out.E[first + p][c] = s.strain(p, c);
        }
      if (prepared.station_offset[e + 1] > prepared.station_offset[e]) {
        element.section_resultants(s.geometry, *prepared.material[e], prepared.rule_kind[e], s.ue,
                                   s.forces, s.moments, dT);
        const int station = prepared.station_offset[e];
        for (int k = 0; k < s.forces.rows(); ++k)
          for (int c = 0; c < 3; ++c) {
            out.SF[station + k][c] = s.forces(k, c);
            out.SM[station + k][c] = s.moments(k, c);
          }
      }
      if (!touches_reaction) continue;

      // Internal force of the element (B-bar, incompatible modes, hourglass forces and the
      // thermal strain included).
      element.internal_force(s.geometry, *prepared.material[e], prepared.rule_kind[e], s.ue, s.fe,
                             options, dT);
      for (int k = 0; k < n; ++k) {
        const int r = reaction_node[prepared.active_of_node[nodes[k]]];
        if (r < 0) continue;
        for (int c = 0; c < m; ++c) s.internal[reaction_first[r] + c] += s.fe(m * k + c);
      }
    }
  });

  // Constraint force in the nodal system, kept on the constrained dofs, reported globally: the
  // force part as RF, the moment part (nodes with rotations) as RM; a *TRANSFORM turns both.
  std::vector<char> constrained(prepared.active_dofs(), 0);
  for (int dof : input.reaction_dofs) constrained[dof] = 1;
  for (std::size_t r = 0; r < node_of_reaction.size(); ++r) {
    const int a = node_of_reaction[r];
    const int first = prepared.dof_offset[a];
    const Eigen::Matrix3d* R = input.rotations != nullptr ? input.rotations->of(a) : nullptr;
    for (int part = 0; part * 3 < prepared.node_dofs(a); ++part) {
      Eigen::Vector3d internal = Eigen::Vector3d::Zero();
      for (const RecoveryScratch& s : scratch)
        for (int d = 0; d < 3; ++d) internal[d] += s.internal[reaction_first[r] + 3 * part + d];
      if (R != nullptr) internal = R->transpose() * internal;
      Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
      for (int d = 0; d < 3; ++d) {
        const int dof = first + 3 * part + d;
        if (constrained[dof]) reaction[d] = internal[d] - input.f[dof];
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
