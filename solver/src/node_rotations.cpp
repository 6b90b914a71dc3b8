#include "node_rotations.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "styk/core/local_axes.hpp"

namespace styk::solver_detail {

NodeRotations NodeRotations::from_transforms(const Model& model, const PreparedModel& prepared) {
  NodeRotations out;
  out.dof_offset_ = prepared.dof_offset;
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
        throw InputError(
            transform.where,
            "*TRANSFORM: the local system is undefined at node " +
                std::to_string(model.node_ids[node]) + ": " +
                (defect.empty() ? "it " + axes_defect_at(transform.axes, model.coords[node])
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

int NodeRotations::node_of(int dof) const {
  return static_cast<int>(std::upper_bound(dof_offset_.begin(), dof_offset_.end(), dof) -
                          dof_offset_.begin()) -
         1;
}

Eigen::Vector3d NodeRotations::direction(int dof) const {
  const int a = node_of(dof);
  const int axis = (dof - dof_offset_[a]) % 3;
  const Eigen::Matrix3d* R = of(a);
  return R != nullptr ? Eigen::Vector3d(R->col(axis)) : Eigen::Vector3d::Unit(axis);
}

bool NodeRotations::rotational(int dof) const { return dof - dof_offset_[node_of(dof)] >= 3; }

void NodeRotations::turn(std::vector<double>& v, bool to_local) const {
  for (std::size_t a = 0; a < rotation_of_node_.size(); ++a) {
    if (rotation_of_node_[a] < 0) continue;
    const Eigen::Matrix3d& R = rotations_[rotation_of_node_[a]];
    for (int first = dof_offset_[a]; first < dof_offset_[a + 1]; first += 3) {
      Eigen::Map<Eigen::Vector3d> block(v.data() + first);
      block = to_local ? Eigen::Vector3d(R.transpose() * block) : Eigen::Vector3d(R * block);
    }
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
      const Eigen::Matrix3d& left = Ra != nullptr ? *Ra : identity;
      const Eigen::Matrix3d& right = Rb != nullptr ? *Rb : identity;
      double* block = values.data() + K.block_start(a, b);
      // Translations and rotations of either node turn with the node's R: 3x3 sub-blocks.
      for (int i0 = 0; i0 < K.node_dofs(a); i0 += 3)
        for (int j0 = 0; j0 < K.node_dofs(b); j0 += 3) {
          Eigen::Matrix3d Kab;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) Kab(r, c) = block[(i0 + r) * stride + j0 + c];
          const Eigen::Matrix3d rotated = left.transpose() * Kab * right;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) block[(i0 + r) * stride + j0 + c] = rotated(r, c);
        }
    }
  }
}

}  // namespace styk::solver_detail
