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

// One slave node's mortar row: D_j (integral of its slave basis function) and M_jk per master node
// k. A mid-edge node of a transformed quadratic slave face (slave_basis_transform) also has its
// own share `own` (3/5) of the basis and the shares of the edge's corners (1/5 each), through
// which its row couples them: D_j (u^_j - sum_k w_k u_k) with u^_j = (u_j - sum_c share_c u_c) /
// own.
struct MortarRow {
  double area = 0.0;
  std::map<int, double> coupling;
  double own = 1.0;
  std::map<int, double> corner_shares;
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
//   a cyclic symmetry boundary (`cyclic_joins`), edges of plane or axisymmetric elements;
// - SURFACE TO SURFACE when the faces are solid element faces whose slave basis (with
//   slave_basis_transform) admits the dual basis and no slave node is joined across a cyclic
//   symmetry boundary; otherwise node to surface, with the reason in `why_not`;
// - NODE TO SURFACE never.
std::optional<std::map<int, MortarRow>> pair_mortar_rows(
    const Model& model, const ContactPair& pair, const Surface& slave_surface,
    std::vector<PlacedFace> slave_faces, const Surface& master_surface,
    const std::vector<PlacedFace>& master_faces, bool cyclic_joins, std::string& why_not);

// Gives `c` the row's area and master terms (weights M_jk / sum_k M_jk, a partition of unity) and
// `master_point` the weighted master point sum_k w_k x_k, so that gap0 = n . (master point - x_j)
// is the weighted gap. A mid-edge node of a transformed face gets the row multiplied by `own`: the
// corners as slave-side terms with their shares, the master weights times `own`, and the area
// D_j / own (= integral N_j dA), so that force / area is the multiplier's pressure. Returns false,
// leaving c alone, when the master covers less than half of the node's dual function (sum_k M_jk <
// D_j / 2): the node lies beyond the master surface.
bool apply_mortar_row(const Model& model, const MortarRow& row, ContactConstraint& c,
                      Eigen::Vector3d& master_point);

}  // namespace styk::contact
