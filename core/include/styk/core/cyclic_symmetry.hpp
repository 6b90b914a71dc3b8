// The node pairs of the model's cyclic symmetry ties (*TIE, CYCLIC SYMMETRY + *CYCLIC SYMMETRY
// MODEL, docs/input.md): every slave-surface node with the master-surface node its rotation by one
// sector angle lands on, and the nodes on the axis. The solver turns them into constraint
// equations (u_master = Q u_slave: a load repeating in every sector), the contact constraints use
// them to join a contact node cut by the sector boundary with its image.
#pragma once

#include <array>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk {

using Matrix3 = std::array<std::array<double, 3>, 3>;  // row-major

struct CyclicNodePair {
  int slave = 0;   // node index
  int master = 0;  // node index: the slave's image under Q
};

struct ResolvedCyclicSymmetry {
  const CyclicSymmetry* definition = nullptr;
  Vec3 point{};        // a point on the axis (CyclicSymmetry::a)
  Vec3 axis{};         // unit axis direction (a -> b)
  double angle = 0.0;  // signed sector angle about `axis` from the slave side to the master side
  Matrix3 rotation{};  // Q: x_master - point = Q (x_slave - point); vectors map the same way
  std::vector<CyclicNodePair> pairs;  // sorted by slave
  std::vector<int> axis_nodes;        // nodes of either surface on the axis, sorted
};

// Resolves every tie of `model`. The slave surface's nodes off the axis must each have a master
// node within the position tolerance (POSITION TOLERANCE=, default 1e-6 of the model's size) of
// their image; the sense of rotation is the one that matches. Throws InputError at the *TIE line
// naming the first node without a match (Styk ties matching meshes only), a master node claimed
// twice, or a node of both surfaces that is not on the axis.
std::vector<ResolvedCyclicSymmetry> resolve_cyclic_symmetries(const Model& model,
                                                              const ElementRegistry& registry);

// The nodes of a surface: its node list, or the nodes of its element faces (sorted, unique).
std::vector<int> surface_node_list(const Model& model, const ElementRegistry& registry,
                                   const Surface& surface);

// Q v.
Vec3 rotate(const Matrix3& Q, const Vec3& v);

}  // namespace styk
