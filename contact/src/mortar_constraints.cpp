#include "mortar_constraints.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace styk::contact {
namespace {

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  bool overlaps(const Box& other, double margin) const {
    return ((lo.array() - margin) <= other.hi.array()).all() &&
           ((hi.array() + margin) >= other.lo.array()).all();
  }
};

Box box_of(const MortarFace& f) {
  Box b;
  for (int local : f.local) {
    b.lo = b.lo.cwiseMin(f.placed.geometry.X.row(local).transpose());
    b.hi = b.hi.cwiseMax(f.placed.geometry.X.row(local).transpose());
  }
  return b;
}

// Adds one slave face's D and M to the rows.
void add_face_rows(const MortarFace& slave, const std::vector<MortarFace>& master,
                   const std::vector<Box>& master_boxes, const SourceLoc& where,
                   std::map<int, MortarRow>& rows) {
  const DualBasis dual = dual_basis(slave, where);
  for (std::size_t a = 0; a < slave.nodes.size(); ++a) {
    MortarRow& row = rows[slave.nodes[a]];
    row.area += dual.nodal_integrals[a];
    if (slave.basis.size() == 0 || slave.basis(a, a) == 1.0) continue;
    // A mid-edge node: the same shares on every face along its edge.
    row.own = slave.basis(a, a);
    for (std::size_t c = 0; c < slave.nodes.size(); ++c)
      if (c != a && slave.basis(c, a) != 0.0) row.corner_shares[slave.nodes[c]] = slave.basis(c, a);
  }
  const Box box = box_of(slave);
  // Master faces within a face size of the slave face and facing it.
  const double margin = (box.hi - box.lo).norm();
  const Eigen::Vector3d normal = face_centre_normal(slave.placed);
  for (std::size_t m = 0; m < master.size(); ++m) {
    if (!box.overlaps(master_boxes[m], margin)) continue;
    if (normal.dot(face_centre_normal(master[m].placed)) >= 0.0) continue;
    Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(slave.nodes.size(), master[m].nodes.size());
    if (integrate_overlap(slave, dual, master[m], coupling) <= 0.0) continue;
    for (std::size_t a = 0; a < slave.nodes.size(); ++a)
      for (std::size_t k = 0; k < master[m].nodes.size(); ++k)
        rows[slave.nodes[a]].coupling[master[m].nodes[k]] += coupling(a, k);
  }
}

}  // namespace

std::vector<MortarFace> mortar_faces(const Model& model, const Surface& surface,
                                     std::vector<PlacedFace> placed, const SourceLoc& where) {
  std::vector<MortarFace> out;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    MortarFace f;
    f.placed = std::move(placed[i]);
    const ElementForm form = f.placed.element->form();
    if (form == ElementForm::Planar || form == ElementForm::Axisymmetric)
      throw InputError(where, "TYPE=MORTAR needs faces of solid elements; surface " + surface.name +
                                  " has an edge of element " +
                                  std::to_string(f.placed.geometry.id));
    f.local = f.placed.element->faces()[f.placed.face].nodes;
    const int* nodes = model.element_nodes(surface.faces[i].element);
    for (int local : f.local) f.nodes.push_back(nodes[local]);
    out.push_back(std::move(f));
  }
  return out;
}

std::map<int, MortarRow> mortar_rows(const std::vector<MortarFace>& slave,
                                     const std::vector<MortarFace>& master,
                                     const SourceLoc& where) {
  std::vector<Box> master_boxes;
  for (const MortarFace& f : master) master_boxes.push_back(box_of(f));
  std::map<int, MortarRow> rows;
  for (const MortarFace& f : slave) add_face_rows(f, master, master_boxes, where, rows);
  return rows;
}

std::optional<std::map<int, MortarRow>> pair_mortar_rows(
    const Model& model, const ContactPair& pair, const Surface& slave_surface,
    std::vector<PlacedFace> slave_faces, const Surface& master_surface,
    const std::vector<PlacedFace>& master_faces, bool cyclic_joins, std::string& why_not) {
  why_not.clear();
  if (pair.type == ContactPair::Type::NodeToSurface) return std::nullopt;
  const bool required = pair.type == ContactPair::Type::Mortar;
  if (slave_surface.kind != Surface::Kind::ElementFaces) {
    if (required)
      throw InputError(
          pair.where, "TYPE=MORTAR needs element faces on the slave surface " + slave_surface.name);
    why_not = "the slave surface is a node surface";
    return std::nullopt;
  }
  if (cyclic_joins) {
    if (required)
      throw InputError(pair.where,
                       "TYPE=MORTAR across a cyclic symmetry boundary is not supported; use NODE "
                       "TO SURFACE");
    why_not = "slave nodes lie on a cyclic symmetry boundary";
    return std::nullopt;
  }
  auto is_edge = [](const PlacedFace& f) {
    const ElementForm form = f.element->form();
    return form == ElementForm::Planar || form == ElementForm::Axisymmetric;
  };
  if (!required && (std::any_of(slave_faces.begin(), slave_faces.end(), is_edge) ||
                    std::any_of(master_faces.begin(), master_faces.end(), is_edge))) {
    why_not = "edges of plane or axisymmetric elements";
    return std::nullopt;
  }
  std::vector<MortarFace> slave =
      mortar_faces(model, slave_surface, std::move(slave_faces), pair.where);
  for (MortarFace& f : slave) f.basis = slave_basis_transform(f);
  if (!required)
    for (const MortarFace& f : slave)
      if (!admits_dual_basis(f)) {
        why_not = "slave element " + std::to_string(f.placed.geometry.id) +
                  " has a face node whose integral of N dA is not positive";
        return std::nullopt;
      }
  return mortar_rows(slave, mortar_faces(model, master_surface, master_faces, pair.where),
                     pair.where);
}

bool apply_mortar_row(const Model& model, const MortarRow& row, ContactConstraint& c,
                      Eigen::Vector3d& master_point) {
  double covered = 0.0;
  for (const auto& [node, m] : row.coupling) covered += m;
  if (!(covered >= 0.5 * row.area)) return false;
  c.master.clear();
  master_point.setZero();
  auto add = [&](int node, double weight, bool slave_side) {
    c.master.push_back({node, weight, slave_side});
    master_point += weight * Eigen::Vector3d(model.coords[node][0], model.coords[node][1],
                                             model.coords[node][2]);
  };
  for (const auto& [node, m] : row.coupling)
    if (std::abs(m) > 1e-14 * row.area) add(node, row.own * m / covered, false);
  for (const auto& [node, share] : row.corner_shares) add(node, share, true);
  c.area = row.area / row.own;
  c.gap_scale = row.own;
  c.node_to_node = false;
  c.mortar = true;
  return true;
}

}  // namespace styk::contact
