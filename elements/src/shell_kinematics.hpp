// Private pieces of the shell elements (shell.hpp): the section and nodal normals of an element
// and the strain operator at a point (covariant strains turned into the lamina axes, MITC4 shear
// for the 4-node element). Shared by the stiffness, load, stress and section-force code.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/elements/shell.hpp"

namespace styk::shell_detail {

// The element's section and material constants and its nodal normals.
struct ShellSetup {
  double thickness = 0.0;
  double offset = 0.0;     // fraction of t from the mid-surface to the reference surface
  int section_points = 5;  // Simpson points through the thickness
  double young = 0.0, poisson = 0.0, shear = 0.0;
  std::vector<Eigen::Vector3d> normals;  // V_a, unit
  // Plane-stress and transverse-shear stiffness of the lamina strains
  // (eps11, eps22, gamma12, gamma13, gamma23).
  Eigen::Matrix<double, 5, 5> D = Eigen::Matrix<double, 5, 5>::Zero();
  // Distance z(zeta) of the fibre point from the reference surface along the normal.
  double z(double zeta) const { return thickness * (0.5 * zeta - offset); }
};

// Checks the node count, the *SHELL SECTION and the material (constant isotropic elasticity) of
// any shell-like element and fills the section and material constants (no normals).
ShellSetup section_setup(const TElement& element, const ElementGeometry& g,
                         const Material& material);

// Lamina axes for a surface normal: e3 along it, e1 the projection of global x (z when x is
// within 0.1 degree of the normal), e2 = e3 x e1 (Abaqus' local shell directions).
Eigen::Matrix3d lamina_axes_of_normal(const Eigen::Vector3d& normal);

// Checks the geometry, the *SHELL SECTION and the material (constant isotropic elasticity) and
// computes the nodal normals. Throws InputError naming the element.
ShellSetup shell_setup(const Shell& shell, const ElementGeometry& g, const Material& material);

// The lamina strains at a point: B (5 x 6n) with rows eps11, eps22, gamma12, gamma13, gamma23 in
// the lamina axes R (columns e1, e2, e3), and det J of the 3D map.
struct LaminaPoint {
  Eigen::MatrixXd B;
  Eigen::Matrix3d R;
  double detJ = 0.0;
  Eigen::VectorXd N;
};
void lamina_point(const Shell& shell, const ElementGeometry& g, const ShellSetup& s, const Vec3& xi,
                  int point, LaminaPoint& out);

// The drilling row at a surface point (zeta = 0): theta . e3 minus the membrane's in-plane
// rotation, and the area measure |g1 x g2| there.
void drilling_row(const Shell& shell, const ElementGeometry& g, const ShellSetup& s, double xi,
                  double eta, Eigen::RowVectorXd& row, double& area);

// A shell's integration rule: each surface point of `surface` with the bottom, middle and top
// fibre (zeta = -1, 0, 1) and Simpson's weights over the thickness, halved so that a point's
// three fibres sum to its surface weight (the point measure carries the thickness).
IntegrationRule with_fibres(const IntegrationRule& surface, const std::string& label);

// The point measure of a shell-like element at a surface point: the area |g1 x g2| times the
// thickness (g.cross_section), and dNdx from the dual basis of (g1, g2, n). Throws InputError
// naming the element and `degenerate` (what a zero area means for its shape) when the tangents
// are parallel or zero.
double surface_point_measure(const TElement& element, const ElementGeometry& g,
                             const Eigen::Ref<const Eigen::MatrixXd>& dN,
                             Eigen::Ref<Eigen::MatrixXd> dNdx, int point,
                             const std::string& degenerate);

// Simpson's rule with n (odd) points on [-1, 1].
void simpson(int n, std::vector<double>& points, std::vector<double>& weights);

// "element 12 (S8R)".
std::string label(const TElement& element, const ElementGeometry& g);

// The penalty factor alpha of the drilling term (times G t).
inline constexpr double kDrillingFactor = 1e-3;

}  // namespace styk::shell_detail
