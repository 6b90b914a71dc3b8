#include "coupling_loads.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "assembly.hpp"
#include "styk/core/local_axes.hpp"

namespace styk::solver_detail {
namespace {

// Nodal areas of the coupling surface (integral of N_i over each face, summed per node).
std::map<int, double> nodal_areas(const Model& model, const PreparedModel& prepared,
                                  const Surface& surface) {
  std::map<int, double> area;
  ElementGeometry g;
  Eigen::VectorXd a;
  for (const SurfaceFace& sf : surface.faces) {
    const TElement& element = *prepared.formulation[sf.element];
    element_geometry(model, prepared, sf.element, g);
    element.nodal_areas(g, sf.face - 1, a);
    const int* nodes = model.element_nodes(sf.element);
    for (int local : element.faces()[sf.face - 1].nodes) area[nodes[local]] += a[local];
  }
  return area;
}

Eigen::Vector3d position(const Model& model, int node) {
  return {model.coords[node][0], model.coords[node][1], model.coords[node][2]};
}

}  // namespace

std::vector<DistributingTransfer> distributing_transfers(const Model& model,
                                                         const PreparedModel& prepared) {
  std::vector<DistributingTransfer> out;
  for (const Coupling& coupling : model.couplings) {
    if (coupling.kind != Coupling::Kind::Distributing) continue;
    DistributingTransfer transfer;
    transfer.reference_node = coupling.reference_node;
    transfer.where = coupling.where;
    transfer.dofs = {1, 2, 3};
    for (int dof : coupling.dofs)
      if (dof > 3) transfer.dofs.push_back(dof);
    const std::map<int, double> area =
        nodal_areas(model, prepared, model.surfaces.at(coupling.surface));
    double total = 0.0;
    for (const auto& [node, a] : area) total += a;
    if (!(total > 0.0))
      throw InputError(coupling.where, "*COUPLING " + coupling.name + ": surface " +
                                           coupling.surface + " has no area");
    // Weights, the weighted centre and the principal axes of the weighted node cloud.
    std::vector<double> w;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& [node, a] : area) {
      transfer.nodes.push_back(node);
      w.push_back(a / total);
      centre += w.back() * position(model, node);
    }
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < w.size(); ++i) {
      const Eigen::Vector3d r = position(model, transfer.nodes[i]) - centre;
      S += w[i] * r * r.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(S);
    Eigen::Matrix3d E;  // e1 (largest), e2, e3 = e1 x e2
    E.col(0) = eigen.eigenvectors().col(2);
    E.col(1) = eigen.eigenvectors().col(1);
    E.col(2) = E.col(0).cross(E.col(1));
    Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  // sum w |r projected off e_k|^2
    for (std::size_t i = 0; i < w.size(); ++i) {
      const Eigen::Vector3d r = position(model, transfer.nodes[i]) - centre;
      for (int k = 0; k < 3; ++k)
        inertia[k] += w[i] * (r - r.dot(E.col(k)) * E.col(k)).squaredNorm();
    }
    // The coupling's load axes: global, or its *ORIENTATION at the reference node.
    Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
    if (!coupling.orientation.empty() &&
        !local_axes_at(model.orientations.at(coupling.orientation).axes,
                       model.coords[coupling.reference_node], A))
      throw InputError(coupling.where, "*COUPLING " + coupling.name +
                                           ": the reference node lies on the axis of its "
                                           "cylindrical ORIENTATION");
    const Eigen::Vector3d offset = position(model, coupling.reference_node) - centre;
    const double largest = inertia.maxCoeff();
    for (std::size_t i = 0; i < w.size(); ++i) {
      const Eigen::Vector3d r = position(model, transfer.nodes[i]) - centre;
      // The forces on node i that carry a moment M about the centre.
      auto moment_force = [&](const Eigen::Vector3d& M) {
        Eigen::Vector3d f = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
          if (!(inertia[k] > 1e-12 * largest)) continue;  // the cloud has no lever about e_k
          const Eigen::Vector3d e = E.col(k);
          f += w[i] * e.cross(r - r.dot(e) * e) * e.dot(M) / inertia[k];
        }
        return f;
      };
      Eigen::Matrix<double, 3, 6> per_load;
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d a = A.col(j);
        per_load.col(j) = w[i] * a + moment_force(offset.cross(a));
        per_load.col(3 + j) = moment_force(a);
      }
      transfer.per_load.push_back(per_load);
    }
    out.push_back(std::move(transfer));
  }
  return out;
}

std::map<int, Eigen::Vector3d> distribute_reference_loads(
    const std::vector<DistributingTransfer>& transfers,
    const std::map<std::pair<int, int>, std::pair<double, SourceLoc>>& reference_loads) {
  std::map<int, Eigen::Vector3d> forces;
  for (const auto& [key, load] : reference_loads) {
    const auto [node, dof] = key;
    bool carried = false;
    for (const DistributingTransfer& t : transfers) {
      if (t.reference_node != node) continue;
      if (std::find(t.dofs.begin(), t.dofs.end(), dof) == t.dofs.end())
        throw InputError(load.second, "*CLOAD on dof " + std::to_string(dof) +
                                          " of the reference node of a distributing coupling "
                                          "whose *DISTRIBUTING does not list it");
      for (std::size_t i = 0; i < t.nodes.size(); ++i) {
        Eigen::Vector3d& f = forces.try_emplace(t.nodes[i], Eigen::Vector3d::Zero()).first->second;
        f += load.first * t.per_load[i].col(dof - 1);
      }
      carried = true;
    }
    if (!carried)
      throw InputError(load.second, "*CLOAD on a node that no distributing coupling refers to");
  }
  return forces;
}

}  // namespace styk::solver_detail
