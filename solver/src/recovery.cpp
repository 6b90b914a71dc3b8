#include "recovery.hpp"

#include "assembly.hpp"
#include "parallel.hpp"

namespace styk::solver_detail {
namespace {

// Scratch of one worker, sized on first use and reused for every element.
struct RecoveryScratch {
  ElementGeometry geometry;
  Eigen::VectorXd ue, fe;
  Eigen::MatrixXd strain, stress;
  std::vector<double> reaction;  // internal force on the compact prescribed dofs
};

}  // namespace

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out) {
  threads = resolve_threads(threads);
  out.U.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  out.RF.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  for (int a = 0; a < prepared.active_nodes(); ++a)
    out.U[prepared.node_of_active[a]] = {u[3 * a], u[3 * a + 1], u[3 * a + 2]};
  out.ip_offset = prepared.ip_offset;
  out.S.assign(prepared.ip_offset.back(), Tensor6{});
  out.E.assign(prepared.ip_offset.back(), Tensor6{});

  // Compact index of each prescribed dof: only elements touching one need the internal force.
  std::vector<int> reaction_index(prepared.active_dofs(), -1);
  for (std::size_t k = 0; k < prescribed.size(); ++k)
    reaction_index[prescribed[k]] = static_cast<int>(k);

  std::vector<RecoveryScratch> scratch(threads);
  for (RecoveryScratch& s : scratch) s.reaction.assign(prescribed.size(), 0.0);
  parallel_for(model.element_count(), threads, 16, [&](int begin, int end, int worker) {
    RecoveryScratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      const int n = model.elements[e].node_count;
      const int* nodes = model.element_nodes(e);
      element_geometry(model, e, s.geometry);
      s.ue.resize(3 * n);
      bool touches_prescribed = false;
      for (int k = 0; k < n; ++k) {
        const int a = prepared.active_of_node[nodes[k]];
        for (int d = 0; d < 3; ++d) {
          s.ue(3 * k + d) = u[3 * a + d];
          touches_prescribed = touches_prescribed || reaction_index[3 * a + d] >= 0;
        }
      }
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      element.strains_stresses(s.geometry, *prepared.material[e], RuleKind::Full, s.ue, s.strain,
                               s.stress, options);
      const int first = prepared.ip_offset[e];
      for (int p = 0; p < s.stress.rows(); ++p)
        for (int c = 0; c < 6; ++c) {
          out.S[first + p][c] = s.stress(p, c);
          out.E[first + p][c] = s.strain(p, c);
        }
      if (!touches_prescribed) continue;

      // Internal force of the element (B-bar, incompatible modes and hourglass forces included).
      element.internal_force(s.geometry, *prepared.material[e], RuleKind::Full, s.ue, s.fe,
                             options);
      for (int k = 0; k < n; ++k) {
        const int a = prepared.active_of_node[nodes[k]];
        for (int d = 0; d < 3; ++d) {
          const int r = reaction_index[3 * a + d];
          if (r >= 0) s.reaction[r] += s.fe(3 * k + d);
        }
      }
    }
  });

  for (std::size_t k = 0; k < prescribed.size(); ++k) {
    double internal = 0.0;
    for (const RecoveryScratch& s : scratch) internal += s.reaction[k];
    const int dof = prescribed[k];
    out.RF[prepared.node_of_active[dof / 3]][dof % 3] = internal - f[dof];
  }
}

}  // namespace styk::solver_detail
