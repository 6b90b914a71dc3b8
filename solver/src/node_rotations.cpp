#include "node_rotations.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "styk/core/local_axes.hpp"

namespace styk::solver_detail {

NodeRotations NodeRotations::from_transforms(const Model& model, const PreparedModel& prepared) {
  NodeRotations out;
  if (model.transforms.empty()) return out;
  out.rotation_of_node_.assign(prepared.active_nodes(), -1);
  for (const Transform& transform : model.transforms) {
    const NodeSet* set = model.find_nset(transform.nset);
    if (set == nullptr)
      throw InputError(transform.where,
                       "*TRANSFORM: node set " + transform.nset + " is not defined");
    for (int node : set->nodes) {
      const int a = prepared.active_of_node[node];
      if (a < 0) continue;
      Eigen::Matrix3d R;
      if (!local_axes_at(transform.axes, model.coords[node], R)) {
        const std::string defect = axes_defect(transform.axes);
        throw InputError(transform.where,
                         "*TRANSFORM: the local system is undefined at node " +
                             std::to_string(model.node_ids[node]) + ": " +
                             (defect.empty() ? "it " + axes_defect_at(transform.axes,
                                                                      model.coords[node])
                                             : defect));
      }
      if (out.rotation_of_node_[a] >= 0)
        throw InputError(transform.where,
                         "*TRANSFORM: node " + std::to_string(model.node_ids[node]) +
                             " already has a local system from another *TRANSFORM");
      out.rotation_of_node_[a] = static_cast<int>(out.rotations_.size());
      out.rotations_.push_back(R);
    }
  }
  if (out.rotations_.empty()) out.rotation_of_node_.clear();
  return out;
}

Eigen::Vector3d NodeRotations::direction(int dof) const {
  const Eigen::Matrix3d* R = of(dof / 3);
  return R != nullptr ? Eigen::Vector3d(R->col(dof % 3)) : Eigen::Vector3d::Unit(dof % 3);
}

void NodeRotations::to_local(std::vector<double>& v) const {
  for (std::size_t a = 0; a < rotation_of_node_.size(); ++a) {
    if (rotation_of_node_[a] < 0) continue;
    Eigen::Map<Eigen::Vector3d> block(v.data() + 3 * a);
    block = rotations_[rotation_of_node_[a]].transpose() * Eigen::Vector3d(block);
  }
}

void NodeRotations::to_global(std::vector<double>& v) const {
  for (std::size_t a = 0; a < rotation_of_node_.size(); ++a) {
    if (rotation_of_node_[a] < 0) continue;
    Eigen::Map<Eigen::Vector3d> block(v.data() + 3 * a);
    block = rotations_[rotation_of_node_[a]] * Eigen::Vector3d(block);
  }
}

void NodeRotations::rotate_stiffness(StiffnessMatrix& K) const {
  if (empty()) return;
  const NodeGraph& graph = K.graph();
  std::vector<double>& values = K.values();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (int a = 0; a < graph.nodes(); ++a) {
    const Eigen::Matrix3d* Ra = of(a);
    const std::int64_t stride = K.row_stride(a);
    for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p) {
      const int b = graph.adj[p];
      const Eigen::Matrix3d* Rb = of(b);
      if (Ra == nullptr && Rb == nullptr) continue;
      double* block = values.data() + K.block_start(a, b);
      Eigen::Matrix3d Kab;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Kab(r, c) = block[r * stride + c];
      const Eigen::Matrix3d rotated =
          (Ra != nullptr ? *Ra : identity).transpose() * Kab * (Rb != nullptr ? *Rb : identity);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) block[r * stride + c] = rotated(r, c);
    }
  }
}

}  // namespace styk::solver_detail
