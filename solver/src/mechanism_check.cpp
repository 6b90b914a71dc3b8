#include "mechanism_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include <Eigen/Eigenvalues>

namespace styk::solver_detail {
namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

std::string node_list(const Model& model, const PreparedModel& prepared,
                      const std::vector<int>& nodes) {
  // The ten smallest ids, in order, read best.
  std::vector<Id> ids;
  ids.reserve(nodes.size());
  for (int a : nodes) ids.push_back(model.node_ids[prepared.node_of_active[a]]);
  const std::size_t shown = std::min<std::size_t>(ids.size(), 10);
  std::partial_sort(ids.begin(), ids.begin() + shown, ids.end());
  std::string list;
  for (std::size_t i = 0; i < shown; ++i) {
    if (i > 0) list += ", ";
    list += std::to_string(ids[i]);
  }
  if (nodes.size() > shown) list += ", ...";
  return list + " (" + std::to_string(nodes.size()) + (nodes.size() == 1 ? " node" : " nodes") +
         ")";
}

// Components below 1e-9 of the largest are round-off of an eigenvector: print them as 0.
std::string format_vector(Eigen::Vector3d v, double scale) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(v[i]) < 1e-9 * scale) v[i] = 0.0;
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z());
  return buffer;
}

// H = sum R_p^T R_p over the part's nodes, R_p = [I, -[p]x] mapping a rigid motion (t, omega) to
// the node's displacement t + omega x p (same centroid and scaling as the restraints), plus
// [0, I] (omega itself) at nodes that carry rotations.
Matrix6 node_motions(const Model& model, const PreparedModel& prepared,
                     const std::vector<int>& part, const Eigen::Vector3d& centroid, double size) {
  Matrix6 H = Matrix6::Zero();
  for (int a : part) {
    const Vec3& x = model.coords[prepared.node_of_active[a]];
    const Eigen::Vector3d p = (Eigen::Vector3d(x[0], x[1], x[2]) - centroid) / size;
    Eigen::Matrix<double, 3, 6> R;
    R.leftCols<3>().setIdentity();
    R.rightCols<3>() << 0.0, p.z(), -p.y(), -p.z(), 0.0, p.x(), p.y(), -p.x(), 0.0;
    H.noalias() += R.transpose() * R;
    if (prepared.node_dofs(a) == kMaxNodeDofs)
      H.bottomRightCorner<3, 3>().diagonal().array() += 1.0;
  }
  return H;
}

// A rigid motion every restraint allows (G m = 0) that moves some node (H m != 0), if any. When
// all nodes lie on one line (a truss bar, a row of bar nodes) the spin about that line moves no
// node: it is no mechanism of the discrete model, so only motions in the range of H are tested.
std::optional<Vector6> free_rigid_motion(const Matrix6& G, const Matrix6& H) {
  const Eigen::SelfAdjointEigenSolver<Matrix6> moves(H);
  int still = 0;  // rigid motions that move no node
  while (still < 6 && !(moves.eigenvalues()[still] > 1e-12 * moves.eigenvalues()[5])) ++still;
  if (still == 0) {
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(G);
    if (eigen.eigenvalues()[0] > 1e-12 * eigen.eigenvalues()[5]) return std::nullopt;
    return Vector6(eigen.eigenvectors().col(0));
  }
  const Eigen::MatrixXd Q = moves.eigenvectors().rightCols(6 - still);
  const Eigen::MatrixXd Gq = Q.transpose() * G * Q;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(Gq);
  const Eigen::Index last = Gq.rows() - 1;
  if (eigen.eigenvalues()[0] > 1e-12 * eigen.eigenvalues()[last]) return std::nullopt;
  return Vector6(Q * eigen.eigenvectors().col(0));
}

}  // namespace

std::vector<std::vector<int>> connected_parts(const NodeGraph& graph) {
  std::vector<int> part(graph.nodes(), -1);
  std::vector<std::vector<int>> parts;
  std::vector<int> stack;
  for (int seed = 0; seed < graph.nodes(); ++seed) {
    if (part[seed] >= 0) continue;
    const int label = static_cast<int>(parts.size());
    parts.emplace_back();
    part[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int a = stack.back();
      stack.pop_back();
      parts.back().push_back(a);
      for (std::int64_t p = graph.ptr[a]; p < graph.ptr[a + 1]; ++p) {
        const int b = graph.adj[p];
        if (part[b] < 0) {
          part[b] = label;
          stack.push_back(b);
        }
      }
    }
    std::sort(parts.back().begin(), parts.back().end());
  }
  return parts;
}

void check_rigid_body_modes(const Model& model, const PreparedModel& prepared,
                            const NodeGraph& graph, const std::vector<int>& prescribed) {
  std::vector<Restraint> restraints;
  restraints.reserve(prescribed.size());
  for (int dof : prescribed) {
    const int component = prepared.component(dof);
    restraints.push_back(
        Restraint{{{prepared.node_of(dof), Eigen::Vector3d::Unit(component % 3), component >= 3}}});
  }
  check_rigid_body_modes(model, prepared, graph, restraints);
}

std::vector<Restraint> with_ring_restraints(const PreparedModel& prepared,
                                            std::vector<Restraint> restraints) {
  for (int a = 0; a < prepared.active_nodes(); ++a)
    if (prepared.ring_node[a]) restraints.push_back(Restraint{{{a, Eigen::Vector3d::UnitX()}}});
  return restraints;
}

void check_rigid_body_modes(const Model& model, const PreparedModel& prepared,
                            const NodeGraph& graph, const std::vector<Restraint>& given) {
  static const char* const kAxis[] = {"x", "y", "z"};
  const std::vector<Restraint> restraints = with_ring_restraints(prepared, given);
  const SourceLoc whole_model{model.source, 0};
  const std::vector<std::vector<int>> parts = connected_parts(graph);
  std::vector<int> part_of(graph.nodes(), -1);
  for (std::size_t k = 0; k < parts.size(); ++k)
    for (int a : parts[k]) part_of[a] = static_cast<int>(k);
  std::vector<std::vector<const Restraint*>> restraints_of(parts.size());
  for (const Restraint& r : restraints)
    if (!r.terms.empty()) restraints_of[part_of[r.terms.front().node]].push_back(&r);

  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::vector<int>& part = parts[k];
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY);
    Eigen::Vector3d hi = -lo;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int a : part) {
      const Vec3& x = model.coords[prepared.node_of_active[a]];
      const Eigen::Vector3d p(x[0], x[1], x[2]);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
      centroid += p;
    }
    centroid /= static_cast<double>(part.size());
    const double size = std::max((hi - lo).maxCoeff(), 1e-300);

    // Rows of G = sum r r^T: each restraint evaluated on the six rigid-body modes (3
    // translations, 3 rotations about the part's centroid, lengths scaled by its size).
    Matrix6 G = Matrix6::Zero();
    for (const Restraint* restraint : restraints_of[k]) {
      Vector6 r = Vector6::Zero();
      for (const RestraintTerm& term : restraint->terms) {
        if (term.rotation) {  // a nodal rotation sees the rigid rotation omega itself
          r.tail<3>() += term.vector;
          continue;
        }
        const Vec3& x = model.coords[prepared.node_of_active[term.node]];
        const Eigen::Vector3d p = (Eigen::Vector3d(x[0], x[1], x[2]) - centroid) / size;
        r.head<3>() += term.vector;
        r.tail<3>() += p.cross(term.vector);
      }
      G.noalias() += r * r.transpose();
    }

    // Translations: first a direction nothing reaches at all (the common mistake), then any
    // direction the restraints leave free.
    for (int d = 0; d < 3; ++d)
      if (!(G(d, d) > 0.0))
        throw InputError(whole_model, std::string("the model can move freely in ") + kAxis[d] +
                                          ": no constraint reaches nodes " +
                                          node_list(model, prepared, part) +
                                          "; constrain at least one of them in " + kAxis[d]);
    const Eigen::Matrix3d Gt = G.topLeftCorner<3, 3>();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> translations(Gt);
    if (!(translations.eigenvalues()[0] > 1e-12 * translations.eigenvalues()[2]))
      throw InputError(whole_model, "the model can move freely along " +
                                        format_vector(translations.eigenvectors().col(0), 1.0) +
                                        ": the constraints on nodes " +
                                        node_list(model, prepared, part) +
                                        " do not hold that direction");

    // Rotations: the restraints must not all be satisfied by a rigid rotation.
    const bool rotations = std::any_of(
        part.begin(), part.end(), [&](int a) { return prepared.node_dofs(a) == kMaxNodeDofs; });
    // A single point without rotational dofs: translations are all it has.
    if (!((hi - lo).maxCoeff() > 0.0) && !rotations) continue;
    const std::optional<Vector6> free =
        free_rigid_motion(G, node_motions(model, prepared, part, centroid, size));
    if (!free) continue;
    const Vector6& mode = *free;
    const Eigen::Vector3d omega = mode.tail<3>();
    if (omega.norm() < 1e-6) continue;  // a translation; already excluded above
    const Eigen::Vector3d t = mode.head<3>();
    const Eigen::Vector3d through = omega.cross(t) / omega.squaredNorm() * size + centroid;
    const Eigen::Vector3d axis = omega.normalized();
    throw InputError(whole_model,
                     "the model can rotate freely about the axis through " +
                         format_vector(through, size) + " along " + format_vector(axis, 1.0) +
                         ": the part with nodes " + node_list(model, prepared, part) +
                         " is held only on one point or line; constrain a node off that axis" +
                         (rotations ? std::string(" or a rotation (dofs 4-6) about it") : ""));
  }
}

}  // namespace styk::solver_detail
