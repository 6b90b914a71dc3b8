// TElement: the base class of every element formulation (the thesis' TElement, made modern).
//
// A derived element supplies only what differs: its node layout and faces, DER (shape functions
// and natural derivatives) and its integration rules; BEE (strain-displacement) and DEE
// (constitutive matrix) have standard defaults. The base class does the rest once (template
// methods): Jacobian and its checks, stiffness, consistent face loads, strains and stresses at the
// integration points. Formulations are stateless; one instance per type lives in the
// ElementRegistry and serves every element of that type.
//
// Conventions
// - Natural coordinates (xi, eta, zeta) in [-1, 1]^3.
// - Strain/stress component order 11, 22, 33, 12, 13, 23 (Abaqus/CalculiX). B uses engineering
//   shear strains (gamma_12 = 2 eps_12); strains reported to users are tensor components.
// - Faces are numbered as Abaqus S1..S6: S1 zeta=-1, S2 zeta=+1, S3 eta=-1, S4 xi=+1, S5 eta=+1,
//   S6 xi=-1.
// - Element matrices are dense, dof order (node 0: x y z, node 1: x y z, ...).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/core/model.hpp"

namespace styk {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

enum class RuleKind { Full, Reduced };

struct IntegrationRule {
  std::string label;                    // e.g. "3x3x3 Gauss"
  std::vector<Vec3> points;             // natural coordinates
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};

// A face of the reference element: the element-local node indices on it (corners first, in the
// Abaqus face order, which circles the face with the normal pointing INTO the element), and the
// natural coordinate it lies on (axis 0/1/2 = xi/eta/zeta, value -1 or +1). Normals are computed
// from axis/value, never from the node order.
struct FaceDef {
  std::vector<int> nodes;
  int axis = 2;
  double value = -1.0;
};

// The element as placed in a model: its nodal coordinates (n x 3) and what to name it in messages.
struct ElementGeometry {
  Eigen::MatrixXd X;                    // node coordinates, one row per element node
  Id id = 0;                            // user element id
  SourceLoc where;                      // the deck line that defined it
};

class TElement {
 public:
  virtual ~TElement() = default;

  // --- node layout -----------------------------------------------------------------------------
  virtual std::string name() const = 0;            // upper-case type name, e.g. "C3D20"
  virtual std::string description() const = 0;     // one line for `styk elements`
  virtual int node_count() const = 0;
  virtual const std::vector<Vec3>& natural_nodes() const = 0;
  virtual const std::vector<FaceDef>& faces() const = 0;  // faces()[0] is S1

  // --- DER: shape functions N (n) and natural derivatives dN (n x 3) at xi ----------------------
  virtual void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                   Eigen::Ref<Eigen::MatrixXd> dN) const = 0;

  // --- integration rules -----------------------------------------------------------------------
  virtual IntegrationRule rule(RuleKind kind) const = 0;
  // Gauss points per direction used to integrate over a face (pressure loads, nodal areas).
  virtual int face_rule_order() const = 0;

  // --- BEE: strain-displacement matrix (6 x 3n) from the Cartesian derivatives dNdx (n x 3) ----
  virtual void bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx, Eigen::Ref<Eigen::MatrixXd> B) const;

  // --- DEE: constitutive matrix from the material (isotropic linear elastic by default) --------
  virtual void dee(const Material& material, Matrix6d& D) const;

  // --- template methods ------------------------------------------------------------------------
  // Cartesian derivatives dNdx (n x 3) and det J at xi. Throws InputError naming the element and
  // the point when det J <= 0 (inverted or degenerate element); `point` is 1-based for messages.
  double jacobian(const ElementGeometry& g, const Eigen::Ref<const Eigen::MatrixXd>& dN,
                  Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const;

  // Stiffness K (3n x 3n) with the given rule.
  void stiffness(const ElementGeometry& g, const Material& material, RuleKind kind,
                 Eigen::MatrixXd& K) const;

  // Consistent nodal forces (3n) of a uniform pressure p on face `face` (0-based: 0 = S1);
  // positive p pushes into the element.
  void pressure_load(const ElementGeometry& g, int face, double p, Eigen::VectorXd& f) const;

  // Equivalent nodal areas A_i = integral of N_i dA over a face (SPEC eq. 2.9), one per element
  // node (zero off the face).
  void nodal_areas(const ElementGeometry& g, int face, Eigen::VectorXd& area) const;

  // Strains (tensor components) and stresses at the integration points of `kind`, one row each
  // (n_points x 6), from the element displacement vector u (3n).
  void strains_stresses(const ElementGeometry& g, const Material& material, RuleKind kind,
                        const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                        Eigen::MatrixXd& stress) const;
};

// Gauss-Legendre points and weights on [-1, 1], n = 1..6.
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights);
// Tensor-product Gauss rule nx x ny x nz, points ordered xi fastest, then eta, then zeta
// (the CalculiX/Abaqus integration-point numbering).
IntegrationRule gauss_rule(int nx, int ny, int nz);

}  // namespace styk
