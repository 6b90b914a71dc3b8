// Mortar (segment-to-segment) rows of a *CONTACT PAIR, TYPE=MORTAR (docs/contact.md, "Mortar
// contact"). With the dual multiplier basis on the slave faces the mortar matrix D is diagonal, so
// the row of slave node j is a ContactConstraint like any other: nodal area D_j = integral N_j dA
// and master terms w_k = M_jk / sum_k M_jk, M_jk = integral phi_j N_k dA over the slave surface.
// A uniform pressure then loads both sides with their consistent nodal forces, which is what the
// contact patch test asks; the solver, friction and results need nothing else.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mortar_segments.hpp"
#include "styk/contact/constraints.hpp"

namespace styk::contact {

// One slave node's mortar row: D_j (its area) and M_jk per master node k.
struct MortarRow {
  double area = 0.0;
  std::map<int, double> coupling;
};

// The faces of element-face surface `surface`, `placed` being its faces placed in order. Throws
// InputError at `where` for an edge of a plane or axisymmetric element.
std::vector<MortarFace> mortar_faces(const Model& model, const Surface& surface,
                                     std::vector<PlacedFace> placed, const SourceLoc& where);

// The rows of every node of the slave faces against the master faces. Throws InputError at `where`
// for a slave face the dual basis does not exist on (dual_basis).
std::map<int, MortarRow> mortar_rows(const std::vector<MortarFace>& slave,
                                     const std::vector<MortarFace>& master, const SourceLoc& where);

// The mortar rows of pair `pair`, or nullopt when it is paired node to surface:
// - TYPE=MORTAR always; InputError at the pair for a node slave surface, slave nodes joined across
//   a cyclic symmetry boundary (`cyclic_joins`), a slave face without dual basis (dual_basis);
// - SURFACE TO SURFACE when every slave face admits the dual basis and no slave node is joined
//   across a cyclic symmetry boundary; otherwise node to surface, with the reason in `why_not`;
// - NODE TO SURFACE never.
std::optional<std::map<int, MortarRow>> pair_mortar_rows(
    const Model& model, const ContactPair& pair, const Surface& slave_surface,
    std::vector<PlacedFace> slave_faces, const Surface& master_surface,
    const std::vector<PlacedFace>& master_faces, bool cyclic_joins, std::string& why_not);

// Gives `c` the row's area and master terms (weights M_jk / sum_k M_jk, a partition of unity) and
// `master_point` the weighted master point sum_k w_k x_k, so that gap0 = n . (master point - x_j)
// is the weighted gap. Returns false, leaving c alone, when the master covers less than half of the
// node's dual function (sum_k M_jk < D_j / 2): the node lies beyond the master surface.
bool apply_mortar_row(const Model& model, const MortarRow& row, ContactConstraint& c,
                      Eigen::Vector3d& master_point);

}  // namespace styk::contact
