#include "distributed_solver.hpp"

#include <algorithm>

#include "rank_partition.hpp"

namespace styk::solver_detail {
namespace {

class DistributedSolver final : public LinearSolver {
 public:
  DistributedSolver(const SolverContext& context, const RankRows& rows, bool direct,
                    double tolerance)
      : context_(context), rows_(rows), direct_(direct), tolerance_(tolerance) {}

  std::string description() const override {
    return system_ ? system_->description() : std::string("distributed solver");
  }

  void prepare(StiffnessMatrix& K, const DofPartition& partition) override {
    const PhaseRecorder::Scope phase(context_.phases, "factorise");
    const PreparedModel& prepared = context_.prepared;
    DistributedSettings settings;
    settings.direct = direct_;
    settings.refine = context_.refine_solutions;
    settings.tolerance = tolerance_;
    settings.block_size = prepared.has_rotations() ? 1 : 3;
    settings.where = SourceLoc{context_.model.source, 0};
    if (!direct_) {
      settings.coarse =
          p_multigrid_requested() ? linear_coarse_space(context_.model, prepared) : std::nullopt;
      if (settings.coarse)
        for (int a : settings.coarse->corner_node)
          for (int d = 0; d < 3; ++d)
            settings.corner_coordinates.push_back(
                context_.model.coords[prepared.node_of_active[a]][d]);
      settings.coordinates.resize(prepared.active_dofs());
      for (int a = 0; a < prepared.active_nodes(); ++a)
        for (int d = 0; d < 3; ++d)
          settings.coordinates[prepared.dof_offset[a] + d] =
              context_.model.coords[prepared.node_of_active[a]][d];
    }
    const CsrView view{K.row_ptr().data(), K.col().data(), K.values().data(), K.rows()};
    system_.reset();
    system_ = std::make_unique<DistributedSystem>(rows_, view, partition, std::move(settings),
                                                  context_.phases);
    // PETSc holds its own copy of this rank's rows: free K's values before the factor or the
    // multigrid hierarchy takes its memory (a later step that needs them reassembles).
    K.release_values();
  }

  std::vector<double> solve(const std::vector<double>& f,
                            const std::vector<double>& prescribed_value) override {
    const PhaseRecorder::Scope phase(context_.phases, "solve");
    return system_->solve(f, prescribed_value);
  }

  int iterations() const override { return system_ ? system_->iterations() : 0; }

  // The direct solver solves blocks of columns at once (the contact compliance's); the iterative
  // one column by column, as the default.
  std::vector<double> solve_homogeneous(const std::vector<double>& F, int columns) override {
    if (!direct_) return LinearSolver::solve_homogeneous(F, columns);
    const PhaseRecorder::Scope phase(context_.phases, "solve");
    return system_->solve_homogeneous(F, columns);
  }

 private:
  SolverContext context_;
  RankRows rows_;
  bool direct_;
  double tolerance_;
  std::unique_ptr<DistributedSystem> system_;
};

}  // namespace

RankShare share_of_rank(const Model& model, const PreparedModel& prepared, const NodeGraph& graph,
                        const MpiWorld& world, const std::vector<int>& rows_every_rank_needs) {
  RankShare share;
  share.rows = partition_rows_by_graph(graph, prepared.dof_offset, world.rank, world.size);
  share.cut_node_pairs = cut_node_pairs(graph, prepared.dof_offset, share.rows);
  // The active nodes whose rows this rank needs whole.
  const int active_nodes = prepared.active_nodes();
  std::vector<char> needed(active_nodes, 0);
  for (int a = 0; a < active_nodes; ++a)
    needed[a] = share.rows.owner(share.rows.row(prepared.dof_offset[a])) == world.rank;
  for (int dof : rows_every_rank_needs) {
    const auto at = std::upper_bound(prepared.dof_offset.begin(),
                                     prepared.dof_offset.begin() + active_nodes + 1, dof);
    needed[static_cast<int>(at - prepared.dof_offset.begin()) - 1] = 1;
  }
  share.assembles_element.assign(model.element_count(), 0);
  for (int e = 0; e < model.element_count(); ++e) {
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count && !share.assembles_element[e]; ++k) {
      const int a = prepared.active_of_node[nodes[k]];
      share.assembles_element[e] = a >= 0 && needed[a];
    }
  }
  return share;
}

std::unique_ptr<LinearSolver> make_distributed_solver(const SolverContext& context,
                                                      const RankRows& rows, bool direct,
                                                      double tolerance) {
  return std::make_unique<DistributedSolver>(context, rows, direct, tolerance);
}

}  // namespace styk::solver_detail
