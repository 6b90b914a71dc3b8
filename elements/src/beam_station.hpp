// Private pieces of the beam elements (beam.hpp): the section constants of an element and the
// kinematics at one point of its axis (shape functions, tangent, section axes, the generalised
// strain operator). Shared by the stiffness, load and stress code.
#pragma once

#include <Eigen/Core>

#include "styk/core/beam_section.hpp"
#include "styk/core/element.hpp"

namespace styk::beam_detail {

// Generalised strains e = (eps, gamma2, gamma1, kappa1, kappa2, phi') and their stiffnesses
// (E A, G A_s2, G A_s1, E I11, E I22, G J); planar beams keep only eps, gamma2, kappa1.
using Vector6 = Eigen::Matrix<double, 6, 1>;

struct ElementSection {
  const BeamSection* section = nullptr;
  BeamSectionProperties properties;
  Vector6 stiffness = Vector6::Zero();  // the diagonal of the section stiffness
  double young = 0.0;
  double poisson = 0.0;
  double shear_modulus = 0.0;
  Vec3 direction{0.0, 0.0, -1.0};  // the approximate first section axis used
};

// The section of element `g` with the material's constants. Throws InputError (at the element,
// the section or the material) for a missing *BEAM SECTION, bad dimensions, a material without
// E and nu, a planar beam off the x-y plane or given a first section axis other than (0, 0, -1).
ElementSection element_section(const TElement& element, const ElementGeometry& g,
                               const Material& material, bool planar);

struct StationFrame {
  Eigen::VectorXd N;      // shape functions
  Eigen::VectorXd dNds;   // derivatives along the axis
  double jacobian = 0.0;  // |dx/dxi|
  Eigen::Vector3d t, n1, n2;
};

// The frame at natural coordinate xi. Throws InputError naming the element for a zero-length
// axis and for a first section axis parallel to the tangent. `point` (1-based) is for messages.
void station_frame(const TElement& element, const ElementGeometry& g, const ElementSection& s,
                   double xi, int point, StationFrame& frame);

// B (6 x 6n): e = B u for the element's dofs u (per node ux, uy, uz, rx, ry, rz).
void strain_operator(const StationFrame& frame, Eigen::MatrixXd& B);

// "element 12 (B31)".
std::string label(const TElement& element, const ElementGeometry& g);

}  // namespace styk::beam_detail
