// Contact constraints: one per slave node of every *CONTACT PAIR, pairing the node with a master
// point (a coincident master node, or its projection on a master face) and giving the local frame,
// the nodal area and the initial gap. Built once from the undeformed geometry (small
// displacements).
//
// Conventions (docs/contact.md):
// - normal n: the slave's nodal normal (SPEC §2.5: normalised mean of the unit face normals of the
//   slave faces sharing the node, evaluated with the element geometry at the node, so curved faces
//   are exact), pointing OUT of the slave body, towards the master;
// - relative displacement d = u_slave - sum_j w_j u_master_j (w: master shape-function values);
// - gap = gap0 - n . d (>= 0; < 0 is penetration); gap0 is the geometric gap along n or *CLEARANCE;
// - multipliers: lambda_n >= 0 is the compressive normal force, lambda_t the tangential force; the
//   force on the slave node is -(lambda_n n + lambda_t1 t1 + lambda_t2 t2), the master points get
//   the opposite, distributed with w.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::contact {

// The friction law of a pair. Coulomb friction in the elliptic form |M^-1 lambda_t| <= lambda_n,
// M = diag(mu1, mu2) along t1, t2 (isotropic: mu1 = mu2); Tied: no slip at all (*FRICTION, ROUGH),
// though the pair may still open.
struct FrictionLaw {
  enum class Kind { Frictionless, Coulomb, Tied };
  Kind kind = Kind::Frictionless;
  double mu1 = 0.0;
  double mu2 = 0.0;
  bool has_tangential() const { return kind != Kind::Frictionless; }
};

struct MasterTerm {
  int node = 0;       // model node index
  double weight = 0;  // shape-function value of the master face at the slave's projection
  // A node of the slave surface itself: the row of a mid-edge node of a quadratic slave face in
  // mortar contact couples it with the edge's corners (docs/contact.md, "Mortar contact"); its
  // force acts on the slave body.
  bool slave_side = false;
};

struct ContactConstraint {
  int pair = 0;                    // index into Model::contact_pairs
  int slave = 0;                   // model node index
  std::vector<MasterTerm> master;  // one term (weight 1) for a node-to-node pair
  bool node_to_node = true;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();
  double area = 0.0;  // nodal contact area: sum of integral N_i dA (SPEC §2.5)
  double gap0 = 0.0;
  // The row is gap_scale times the node's gap and slip: 1, except the mortar row of a mid-edge node
  // of a quadratic slave face (3/5, docs/contact.md "Mortar contact"). gap0, the springs and the
  // row's d are in row units; the results divide by it.
  double gap_scale = 1.0;
  bool mortar = false;  // a mortar row (dual multiplier of a slave node), not a node's projection
  FrictionLaw law;
  // Penalty laws of *SURFACE BEHAVIOR (penalty_law.hpp): the spring stiffness K A of the node
  // (force per length; 0: exact contact, the default) and whether the spring is TIED (never
  // opens, acts in all three directions; law is then FrictionLaw::Kind::Tied).
  double penalty_stiffness = 0.0;
  bool bonded = false;
  // The EXPONENTIAL law's spring: the force A p0 at zero clearance (0: another law) and the decay
  // beta = ln(100) / c0; the node carries A p0 exp(-beta clearance) while closer than c0.
  double exponential_force0 = 0.0;
  double exponential_beta = 0.0;
  // The spring's compliance 1 / (K A) (length per force), 0 for exact contact.
  double penalty_compliance() const {
    return penalty_stiffness > 0.0 ? 1.0 / penalty_stiffness : 0.0;
  }
  // The largest compliance the spring has: 1 / (K A), or the exponential law's at its least force
  // A p0 / 100, 1 / (beta A p0 / 100).
  double largest_spring_compliance() const {
    if (exponential_force0 > 0.0) return 100.0 / (exponential_beta * exponential_force0);
    return penalty_compliance();
  }

  // Row c (0 = normal, 1, 2 = tangential) of the generalised constraint operator: the direction
  // whose dot product with d gives the generalised displacement dtilde_c. Tangential rows are
  // scaled by mu (Coulomb) so that the friction law is isotropic with coefficient 1 in the scaled
  // variables (lambda_t = mu_c * lambdatilde_c); tied rows are unscaled.
  Eigen::Vector3d row(int c) const;
  // Tangential scale of component c (1 or 2): mu_c for Coulomb, 1 for tied, 0 for frictionless.
  double scale(int c) const;
};

// Builds the constraints of every pair of `model` (elements resolved through `registry`). Throws
// InputError at the pair's line for an unknown element type on a surface or a degenerate face
// normal. A slave node that no master face reaches (projection outside every face by more than
// 1e-3 in face coordinates) is left unconstrained, and a slave node of two pairs is constrained
// by the first only; `notes` (may be null) receives one line per such decision.
std::vector<ContactConstraint> build_contact_constraints(const Model& model,
                                                         const ElementRegistry& registry,
                                                         std::vector<std::string>* notes);

// A tangent frame (t1, t2) for unit normal n: t1 is `preferred` projected on the tangent plane
// (when it is not nearly parallel to n; otherwise the global axis least aligned with n), and
// t2 = n x t1.
void tangent_frame(const Eigen::Vector3d& n, const Eigen::Vector3d* preferred, Eigen::Vector3d& t1,
                   Eigen::Vector3d& t2);

}  // namespace styk::contact
