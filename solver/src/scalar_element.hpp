// Element equations of a steady scalar field (heat conduction, electric conduction), written once
// for every formulation through the TElement hooks (DER, point_measure, face_quadrature) and the
// element's own integration rule, so plug-in elements need no code of their own:
//   conductance   K_ij = integral of grad N_i . diag(k) grad N_j dV
//   face flux     f_i  = integral of q N_i dA over one face (q into the body positive)
//   gradient      grad phi at the integration points, flux = -diag(k) grad phi
// Plane elements integrate over their thickness and trusses over their area (point_measure).
#pragma once

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk::solver_detail {

// Conductance K (n x n) with diagonal conductivity k over `rule`.
void scalar_conductance(const TElement& element, const ElementGeometry& g,
                        const IntegrationRule& rule, const Eigen::Vector3d& k, Eigen::MatrixXd& K);

// Gradients of the element field phi (n nodal values) at the points of `rule`, one row each.
void scalar_gradients(const TElement& element, const ElementGeometry& g,
                      const IntegrationRule& rule, const Eigen::Ref<const Eigen::VectorXd>& phi,
                      Eigen::MatrixXd& gradients);

// Consistent nodal flows (n) of a uniform flux q on face `face` (0-based: 0 = S1).
void scalar_face_flux(const TElement& element, const ElementGeometry& g, int face, double q,
                      Eigen::VectorXd& f);

// Whether `rule` has enough points for a conductance without zero-energy modes besides the
// constant field (C3D8R's single point has not): the rank bound points x dimensions must reach
// nodes - 1.
bool rule_resolves_scalar_field(const TElement& element, const IntegrationRule& rule);

}  // namespace styk::solver_detail
