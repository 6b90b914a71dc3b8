#include "styk/contact/constraints.hpp"
#include "styk/contact/penalty_law.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mortar_constraints.hpp"
#include "styk/core/cyclic_symmetry.hpp"
#include "styk/core/local_axes.hpp"
#include "surface_geometry.hpp"

namespace styk::contact {
namespace {

// What a pair sees of one of its surfaces.
struct SurfaceFaces {
  std::vector<PlacedFace> faces;
  std::vector<Eigen::Vector3d> lo, hi;  // bounding box per face
};

const TElement& formulation(const Model& model, const ElementRegistry& registry, int element,
                            const SourceLoc& where) {
  const TElement* found = registry.find(model.elements[element].type);
  if (found == nullptr)
    throw InputError(where, "contact surface on element " +
                                std::to_string(model.elements[element].id) + " of type " +
                                model.elements[element].type + ", which no element provides");
  return *found;
}

SurfaceFaces place_faces(const Model& model, const ElementRegistry& registry,
                         const Surface& surface, const SourceLoc& where) {
  SurfaceFaces out;
  for (const SurfaceFace& sf : surface.faces) {
    PlacedFace f;
    f.element = &formulation(model, registry, sf.element, where);
    f.face = sf.face - 1;
    if (f.face < 0 || f.face >= static_cast<int>(f.element->faces().size()))
      throw InputError(where, "surface " + surface.name + " names face S" +
                                  std::to_string(sf.face) + " of element " +
                                  std::to_string(model.elements[sf.element].id) +
                                  ", which it does not have");
    const Element& element = model.elements[sf.element];
    const int* nodes = model.element_nodes(sf.element);
    f.geometry.X.resize(element.node_count, 3);
    for (int k = 0; k < element.node_count; ++k)
      for (int d = 0; d < 3; ++d) f.geometry.X(k, d) = model.coords[nodes[k]][d];
    f.geometry.id = element.id;
    f.geometry.where = element.where;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (int local : f.element->faces()[f.face].nodes) {
      lo = lo.cwiseMin(f.geometry.X.row(local).transpose());
      hi = hi.cwiseMax(f.geometry.X.row(local).transpose());
    }
    out.faces.push_back(std::move(f));
    out.lo.push_back(lo);
    out.hi.push_back(hi);
  }
  return out;
}

Eigen::Vector3d position(const Model& model, int node) {
  return {model.coords[node][0], model.coords[node][1], model.coords[node][2]};
}

FrictionLaw friction_law(const SurfaceInteraction& interaction) {
  FrictionLaw law;
  if (interaction.behavior.law == PressureOverclosure::Law::Tied) {
    // Springs in all three directions, unscaled like the tied rows of ROUGH.
    law.kind = FrictionLaw::Kind::Tied;
    law.mu1 = law.mu2 = 1.0;
    return law;
  }
  if (!interaction.friction) return law;
  const Friction& f = *interaction.friction;
  if (f.kind == Friction::Kind::Rough) {
    law.kind = FrictionLaw::Kind::Tied;
    law.mu1 = law.mu2 = 1.0;
    return law;
  }
  law.mu1 = f.mu;
  law.mu2 = f.kind == Friction::Kind::Anisotropic ? f.mu2 : f.mu;
  if (law.mu1 > 0.0 || law.mu2 > 0.0) law.kind = FrictionLaw::Kind::Coulomb;
  return law;
}

// Slave nodes of an element-face surface with their averaged unit normals, summed areas
// A_i = integral of N_i dA and summed area vectors V_i = integral of N_i n dA (n: the faces'
// outward unit normal).
struct SlaveNode {
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  double area = 0.0;
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero();

  // The node's area projected on its normal, V_i . n_i: the area on which a uniform pressure p on
  // the faces puts the normal force p V_i . n_i on the node, so the node's normal force over it
  // is p exactly. On a flat surface it is A_i (SPEC §2.5); on a curved one A_i is off by O(alpha^2)
  // (alpha: the faces' angle), in opposite directions at corner and mid-edge nodes of quadratic
  // faces (measured on the SPEC 3.2.2 cylinders, C3D21 with 4 elements around the quarter:
  // pressures +0.77 % / -0.39 % with A_i, docs/contact.md "Nodal area").
  double projected_area(const Eigen::Vector3d& normal) const { return area_vector.dot(normal); }
};

std::map<int, SlaveNode> slave_nodes_of_faces(const Model& model, const SurfaceFaces& slave,
                                              const Surface& surface, const SourceLoc& where) {
  std::map<int, SlaveNode> out;
  Eigen::VectorXd area, area_vectors;
  for (std::size_t i = 0; i < slave.faces.size(); ++i) {
    const PlacedFace& f = slave.faces[i];
    const int* nodes = model.element_nodes(surface.faces[i].element);
    f.element->nodal_areas(f.geometry, f.face, area);
    // A pressure of -1 pulls the face outward: the consistent nodal forces are the area vectors.
    f.element->pressure_load(f.geometry, f.face, -1.0, area_vectors);
    for (int local : f.element->faces()[f.face].nodes) {
      const std::array<double, 2> pq = face_coordinates(f, f.element->natural_nodes()[local]);
      const Eigen::Vector3d n = outward_normal(f, pq[0], pq[1]);
      if (n.isZero())
        throw InputError(where, "surface " + surface.name + ": face S" +
                                    std::to_string(f.face + 1) + " of element " +
                                    std::to_string(f.geometry.id) +
                                    " is degenerate at one of its nodes (no normal)");
      SlaveNode& s = out[nodes[local]];
      s.normal_sum += n;
      s.area += area[local];
      s.area_vector += area_vectors.segment<3>(3 * local);
    }
  }
  return out;
}

// Master nodes sorted by x for the coincident-node search.
class NodeLocator {
 public:
  NodeLocator(const Model& model, const std::set<int>& nodes, double tolerance)
      : model_(model), tolerance_(tolerance) {
    for (int n : nodes) by_x_.emplace_back(model.coords[n][0], n);
    std::sort(by_x_.begin(), by_x_.end());
  }
  int find(const Eigen::Vector3d& x) const {
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(), std::make_pair(x[0] - tolerance_, -1));
    for (; it != by_x_.end() && it->first <= x[0] + tolerance_; ++it)
      if ((position(model_, it->second) - x).norm() <= tolerance_) return it->second;
    return -1;
  }

 private:
  const Model& model_;
  double tolerance_;
  std::vector<std::pair<double, int>> by_x_;
};

double model_size(const Model& model) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (int n = 0; n < model.node_count(); ++n) {
    lo = lo.cwiseMin(position(model, n));
    hi = hi.cwiseMax(position(model, n));
  }
  return model.node_count() > 0 ? (hi - lo).norm() : 1.0;
}

// A contact node cut by a cyclic symmetry boundary (docs/contact.md, "Cyclic symmetry"): the
// slave-side copy and its master-side image are one node of the structure, whose faces lie on
// both sides of the boundary. The constraint stays on the image, with the faces of the copy
// turned onto it (normal sum and area added); the copy's own constraint would repeat it. Returns
// how many were joined.
int join_cyclic_copies(const std::vector<ResolvedCyclicSymmetry>& ties,
                       std::map<int, SlaveNode>& slaves) {
  int joined = 0;
  for (const ResolvedCyclicSymmetry& tie : ties) {
    Eigen::Matrix3d Q;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Q(i, j) = tie.rotation[i][j];
    for (const CyclicNodePair& pair : tie.pairs) {
      const auto copy = slaves.find(pair.slave);
      const auto image = slaves.find(pair.master);
      if (copy == slaves.end() || image == slaves.end()) continue;
      image->second.normal_sum += Q * copy->second.normal_sum;
      image->second.area += copy->second.area;
      image->second.area_vector += Q * copy->second.area_vector;
      slaves.erase(copy);
      ++joined;
    }
  }
  return joined;
}

}  // namespace

Eigen::Vector3d ContactConstraint::row(int c) const {
  if (c == 0) return normal;
  return scale(c) * (c == 1 ? t1 : t2);
}

double ContactConstraint::scale(int c) const {
  if (c == 0) return 1.0;
  switch (law.kind) {
    case FrictionLaw::Kind::Frictionless:
      return 0.0;
    case FrictionLaw::Kind::Tied:
      return 1.0;
    case FrictionLaw::Kind::Coulomb:
      return c == 1 ? law.mu1 : law.mu2;
  }
  return 0.0;
}

void tangent_frame(const Eigen::Vector3d& n, const Eigen::Vector3d* preferred, Eigen::Vector3d& t1,
                   Eigen::Vector3d& t2) {
  auto projected = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(v - v.dot(n) * n); };
  t1 = Eigen::Vector3d::Zero();
  if (preferred != nullptr) t1 = projected(*preferred);
  if (t1.norm() < 1e-6) {
    int least = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n[k]) < std::abs(n[least]) - 1e-12) least = k;
    t1 = projected(Eigen::Vector3d::Unit(least));
  }
  t1.normalize();
  t2 = n.cross(t1);
}

std::vector<ContactConstraint> build_contact_constraints(const Model& model,
                                                         const ElementRegistry& registry,
                                                         std::vector<std::string>* notes) {
  std::vector<ContactConstraint> out;
  std::set<int> constrained;
  const double coincidence = 1e-8 * model_size(model);
  auto note = [&](const std::string& line) {
    if (notes != nullptr) notes->push_back(line);
  };
  const std::vector<ResolvedCyclicSymmetry> cyclic = resolve_cyclic_symmetries(model, registry);

  for (std::size_t p = 0; p < model.contact_pairs.size(); ++p) {
    const ContactPair& pair = model.contact_pairs[p];
    auto lookup = [&](const std::string& name) -> const Surface& {
      const auto it = model.surfaces.find(name);
      if (it == model.surfaces.end())
        throw InputError(pair.where,
                         "*CONTACT PAIR names surface " + name + ", which is not defined");
      return it->second;
    };
    const Surface& slave_surface = lookup(pair.slave);
    const Surface& master_surface = lookup(pair.master);
    if (master_surface.kind != Surface::Kind::ElementFaces)
      throw InputError(pair.where, "the master surface " + master_surface.name +
                                       " of a contact pair must consist of element faces");
    const auto interaction = model.surface_interactions.find(pair.interaction);
    if (interaction == model.surface_interactions.end())
      throw InputError(pair.where, "*CONTACT PAIR names interaction " + pair.interaction +
                                       ", which is not defined");
    check_penalty_law(interaction->second);
    const FrictionLaw law = friction_law(interaction->second);
    const Orientation* orientation = nullptr;
    if (interaction->second.friction && !interaction->second.friction->orientation.empty()) {
      const auto o = model.orientations.find(interaction->second.friction->orientation);
      if (o == model.orientations.end())
        throw InputError(interaction->second.friction->where,
                         "*FRICTION names orientation " +
                             interaction->second.friction->orientation + ", which is not defined");
      orientation = &o->second;
    }
    const NodeSet* adjust = pair.adjust_nset.empty() ? nullptr : model.find_nset(pair.adjust_nset);

    const SurfaceFaces master = place_faces(model, registry, master_surface, pair.where);
    std::set<int> master_nodes;
    for (std::size_t i = 0; i < master.faces.size(); ++i) {
      const int* nodes = model.element_nodes(master_surface.faces[i].element);
      for (int local : master.faces[i].element->faces()[master.faces[i].face].nodes)
        master_nodes.insert(nodes[local]);
    }
    const NodeLocator locator(model, master_nodes, coincidence);

    std::map<int, SlaveNode> slaves;
    std::vector<PlacedFace> slave_faces;
    if (slave_surface.kind == Surface::Kind::ElementFaces) {
      SurfaceFaces placed = place_faces(model, registry, slave_surface, pair.where);
      slaves = slave_nodes_of_faces(model, placed, slave_surface, pair.where);
      slave_faces = std::move(placed.faces);
    } else {
      for (int n : slave_surface.nodes) slaves[n] = SlaveNode{};
    }

    const int joined = join_cyclic_copies(cyclic, slaves);
    if (joined > 0)
      note("contact pair " + pair.slave + "/" + pair.master + ": " + std::to_string(joined) +
           " slave nodes on the cyclic symmetry boundary are joined with their images");
    std::string why_node_to_surface;
    const std::optional<std::map<int, MortarRow>> mortar =
        pair_mortar_rows(model, pair, slave_surface, std::move(slave_faces), master_surface,
                         master.faces, joined > 0, why_node_to_surface);
    if (!why_node_to_surface.empty())
      note("contact pair " + pair.slave + "/" + pair.master +
           ": TYPE=SURFACE TO SURFACE is paired node to surface (" + why_node_to_surface + ")");
    int skipped_shared = 0, skipped_outside = 0;
    for (const auto& [node, s] : slaves) {
      if (constrained.count(node) != 0) {
        ++skipped_shared;
        continue;
      }
      ContactConstraint c;
      c.pair = static_cast<int>(p);
      c.slave = node;
      c.law = law;
      const Eigen::Vector3d xs = position(model, node);
      bool have_normal = !s.normal_sum.isZero();
      if (have_normal) c.normal = s.normal_sum.normalized();
      c.area = have_normal ? s.projected_area(c.normal) : 0.0;

      const int coincident = locator.find(xs);
      Eigen::Vector3d master_point = xs;
      if (mortar) {
        const auto row = mortar->find(node);
        if (row == mortar->end() || !apply_mortar_row(model, row->second, c, master_point)) {
          ++skipped_outside;
          continue;
        }
        // The dual integral D_j projected on the normal like A_i (the dual basis admits only
        // positive A_i).
        if (s.area > 0.0) c.area *= s.projected_area(c.normal) / s.area;
      } else if (coincident >= 0 && coincident != node) {
        c.master.push_back({coincident, 1.0});
        master_point = position(model, coincident);
      } else {
        // Node-to-surface: the master face whose closest point lies inside it (or least outside),
        // nearest among those.
        int best = -1;
        Projection best_projection;
        double best_outside = INFINITY, best_distance = INFINITY;
        for (std::size_t i = 0; i < master.faces.size(); ++i) {
          const double reach = (master.hi[i] - master.lo[i]).norm();
          if (((master.lo[i].array() - reach) > xs.array()).any() ||
              ((master.hi[i].array() + reach) < xs.array()).any())
            continue;
          const Projection pr = project_on_face(master.faces[i], xs);
          if (!pr.converged || pr.normal.isZero()) continue;
          const double outside = pr.outside() <= 1e-6 ? 0.0 : pr.outside();
          const double distance = (pr.x - xs).norm();
          if (outside < best_outside || (outside == best_outside && distance < best_distance)) {
            best = static_cast<int>(i);
            best_projection = pr;
            best_outside = outside;
            best_distance = distance;
          }
        }
        if (best < 0 || best_outside > 1e-3) {
          ++skipped_outside;
          continue;
        }
        const PlacedFace& f = master.faces[best];
        const Eigen::VectorXd N =
            shape_values(*f.element, face_point(f, best_projection.p, best_projection.q));
        const int* nodes = model.element_nodes(master_surface.faces[best].element);
        double sum = 0.0;
        for (int local : f.element->faces()[f.face].nodes)
          if (std::abs(N[local]) > 1e-14) {
            c.master.push_back({nodes[local], N[local]});
            sum += N[local];
          }
        for (MasterTerm& t : c.master) t.weight /= sum;  // exact partition of unity
        c.node_to_node = false;
        master_point = best_projection.x;
        if (!have_normal) {
          c.normal = -best_projection.normal;
          have_normal = true;
        }
      }
      if (!have_normal)
        throw InputError(pair.where, "slave node " + std::to_string(model.node_ids[node]) +
                                         " has no normal (node surface on a coincident node)");
      // The spring on the pairing's area (mortar: D_j); a row that is gap_scale times the node's
      // gap (a mortar mid-edge row) has its spring and clearance scaled with it.
      apply_penalty_law(interaction->second, slave_surface, std::to_string(model.node_ids[node]),
                        c);
      c.penalty_stiffness /= c.gap_scale;
      c.exponential_beta /= c.gap_scale;
      c.gap0 = c.normal.dot(master_point - xs);
      if (pair.clearance) c.gap0 = *pair.clearance * c.gap_scale;
      if ((adjust != nullptr &&
           std::binary_search(adjust->nodes.begin(), adjust->nodes.end(), node)) ||
          (pair.adjust_tolerance && std::abs(c.gap0) <= *pair.adjust_tolerance * c.gap_scale))
        c.gap0 = 0.0;
      // The orientation's local 1 axis at the node; a node on a cylindrical orientation's axis has
      // none and takes the default tangent.
      Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
      const bool oriented =
          orientation != nullptr && local_axes_at(orientation->axes, model.coords[node], axes);
      const Eigen::Vector3d preferred = axes.col(0);
      tangent_frame(c.normal, oriented ? &preferred : nullptr, c.t1, c.t2);
      constrained.insert(node);
      out.push_back(std::move(c));
    }
    if (skipped_shared > 0)
      note("contact pair " + pair.slave + "/" + pair.master + ": " +
           std::to_string(skipped_shared) + " slave nodes already belong to an earlier pair");
    if (skipped_outside > 0)
      note("contact pair " + pair.slave + "/" + pair.master + ": " +
           std::to_string(skipped_outside) +
           " slave nodes lie beyond the master surface and are not constrained");
  }
  return out;
}

}  // namespace styk::contact
