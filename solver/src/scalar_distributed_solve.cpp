#include <algorithm>
#include <numeric>

#include "distributed_system.hpp"
#include "rank_partition.hpp"
#include "scalar_linear_solve.hpp"

namespace styk::solver_detail {
namespace {

// The node graph of a scalar field's matrix (one dof per node): its pattern.
NodeGraph graph_of(const Eigen::SparseMatrix<double>& K) {
  NodeGraph graph;
  graph.ptr.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
  graph.adj.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
  return graph;
}

class DistributedScalarSolve final : public ScalarLinearSolve {
 public:
  DistributedScalarSolve(const Eigen::SparseMatrix<double>& K,
                         const std::map<int, double>& prescribed, const SourceLoc& where,
                         const MpiWorld& world, const PhaseRecorder& phases) {
    const int n = static_cast<int>(K.rows());
    std::vector<int> fixed;
    for (const auto& entry : prescribed) fixed.push_back(entry.first);
    partition_ = partition_dofs(n, fixed);
    std::vector<int> one_per_node(n + 1);
    std::iota(one_per_node.begin(), one_per_node.end(), 0);
    const RankRows rows =
        partition_rows_by_graph(graph_of(K), one_per_node, world.rank, world.size);
    // K is symmetric and compressed column-major: its columns are its rows.
    const CsrView view{K.outerIndexPtr(), K.innerIndexPtr(), K.valuePtr(), n};
    // Every rank assembled the whole conductance: each adds the rows it owns.
    DistributedSettings settings;
    settings.direct = true;
    settings.residual_limit = 1e-8;  // as the serial solve
    settings.what = "conductance";
    settings.where = where;
    system_ =
        std::make_unique<DistributedSystem>(rows, view, partition_, std::move(settings), phases);
  }

  int free_count() const override { return partition_.free_count(); }

  bool same_partition(const std::map<int, double>& prescribed) const override {
    if (prescribed.size() != partition_.prescribed.size()) return false;
    for (const auto& entry : prescribed)
      if (partition_.free_of_dof[entry.first] >= 0) return false;
    return true;
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& f, const std::map<int, double>& prescribed,
                        const SourceLoc&) override {
    std::vector<double> values(f.size(), 0.0);
    for (const auto& [u, value] : prescribed) values[u] = value;
    const std::vector<double> phi =
        system_->solve(std::vector<double>(f.data(), f.data() + f.size()), values);
    return Eigen::Map<const Eigen::VectorXd>(phi.data(), static_cast<Eigen::Index>(phi.size()));
  }

  std::string description() const override { return system_->description(); }

 private:
  DofPartition partition_;
  std::unique_ptr<DistributedSystem> system_;
};

}  // namespace

std::unique_ptr<ScalarLinearSolve> make_distributed_scalar_solve(
    const Eigen::SparseMatrix<double>& K, const std::map<int, double>& prescribed,
    const SourceLoc& where, const MpiWorld& world, const PhaseRecorder& phases) {
  return std::make_unique<DistributedScalarSolve>(K, prescribed, where, world, phases);
}

}  // namespace styk::solver_detail
