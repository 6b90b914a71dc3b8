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
  Eigen::MatrixXd strain, stress;
  std::vector<double> internal;  // internal force (global) on the compact reaction nodes
};

}  // namespace

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const RecoveryInput& input, int threads, IncrementResult& out) {
  threads = resolve_threads(threads);
  const std::vector<double>& u = input.u;
  out.U.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  out.RF.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  for (int a = 0; a < prepared.active_nodes(); ++a)
    out.U[prepared.node_of_active[a]] = {u[3 * a], u[3 * a + 1], u[3 * a + 2]};
  out.ip_offset = prepared.ip_offset;
  out.S.assign(prepared.ip_offset.back(), Tensor6{});
  out.E.assign(prepared.ip_offset.back(), Tensor6{});

  // Compact index of each node with a constrained dof: only elements touching one need the
  // internal force.
  std::vector<int> reaction_node(prepared.active_nodes(), -1);
  std::vector<int> node_of_reaction;
  for (int dof : input.reaction_dofs)
    if (reaction_node[dof / 3] < 0) {
      reaction_node[dof / 3] = static_cast<int>(node_of_reaction.size());
      node_of_reaction.push_back(dof / 3);
    }

  std::vector<RecoveryScratch> scratch(threads);
  for (RecoveryScratch& s : scratch) s.internal.assign(3 * node_of_reaction.size(), 0.0);
  parallel_for(model.element_count(), threads, 16, [&](int begin, int end, int worker) {
    RecoveryScratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      const int n = model.elements[e].node_count;
      const int* nodes = model.element_nodes(e);
      element_geometry(model, e, s.geometry);
      s.ue.resize(3 * n);
      bool touches_reaction = false;
      for (int k = 0; k < n; ++k) {
        const int a = prepared.active_of_node[nodes[k]];
        for (int d = 0; d < 3; ++d) s.ue(3 * k + d) = u[3 * a + d];
        touches_reaction = touches_reaction || reaction_node[a] >= 0;
      }
      const Eigen::VectorXd* dT = nullptr;
      if (input.nodal_dT != nullptr) {
        element_temperature_changes(model, e, *input.nodal_dT, s.dT);
        if (!s.dT.isZero(0.0)) dT = &s.dT;
      }
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      element.strains_stresses(s.geometry, *prepared.material[e], RuleKind::Full, s.ue, s.strain,
                               s.stress, options, dT);
      const int first = prepared.ip_offset[e];
      for (int p = 0; p < s.stress.rows(); ++p)
        for (int c = 0; c < 6; ++c) {
          out.S[first + p][c] = s.stress(p, c);
          out.E[first + p][c] = s.strain(p, c);
        }
      if (!touches_reaction) continue;

      // Internal force of the element (B-bar, incompatible modes, hourglass forces and the
      // thermal strain included).
      element.internal_force(s.geometry, *prepared.material[e], RuleKind::Full, s.ue, s.fe, options,
                             dT);
      for (int k = 0; k < n; ++k) {
        const int r = reaction_node[prepared.active_of_node[nodes[k]]];
        if (r < 0) continue;
        for (int d = 0; d < 3; ++d) s.internal[3 * r + d] += s.fe(3 * k + d);
      }
    }
  });

  // Constraint force in the nodal system, kept on the constrained dofs, reported globally.
  std::vector<char> constrained(prepared.active_dofs(), 0);
  for (int dof : input.reaction_dofs) constrained[dof] = 1;
  for (std::size_t r = 0; r < node_of_reaction.size(); ++r) {
    const int a = node_of_reaction[r];
    Eigen::Vector3d internal = Eigen::Vector3d::Zero();
    for (const RecoveryScratch& s : scratch)
      for (int d = 0; d < 3; ++d) internal[d] += s.internal[3 * r + d];
    const Eigen::Matrix3d* R = input.rotations != nullptr ? input.rotations->of(a) : nullptr;
    if (R != nullptr) internal = R->transpose() * internal;
    Eigen::Vector3d rf = Eigen::Vector3d::Zero();
    for (int d = 0; d < 3; ++d)
      if (constrained[3 * a + d]) rf[d] = internal[d] - input.f[3 * a + d];
    if (R != nullptr) rf = *R * rf;
    out.RF[prepared.node_of_active[a]] = {rf[0], rf[1], rf[2]};
  }
}

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out) {
  recover_increment(model, prepared, RecoveryInput{prescribed, u, f}, threads, out);
}

}  // namespace styk::solver_detail
