// Closed-form solutions of the atlas' reference problems (docs/accuracy.md names the sources).
// An exact solution gives the displacement and the stress (or, for heat, the temperature and its
// gradient) at any point of a body; `region` is the element's section index, so the bodies of a
// contact problem each have their own field.
#pragma once

#include <memory>

#include "styk/core/results.hpp"

namespace styk::studies {

class ExactSolution {
 public:
  virtual ~ExactSolution() = default;
  // True for a scalar field (steady heat): temperature() and gradient() are defined instead of
  // displacement() and stress().
  virtual bool scalar() const { return false; }
  virtual Vec3 displacement(const Vec3& x, int region) const;
  virtual Tensor6 stress(const Vec3& x, int region) const;  // 11 22 33 12 13 23
  virtual double temperature(const Vec3& x) const;
  virtual Vec3 gradient(const Vec3& x) const;
  // Conductivity (heat) or Young's modulus and Poisson's ratio of `region`, for the energy norm.
  virtual double conductivity() const { return 1.0; }
  virtual double young(int region) const = 0;
  virtual double poisson(int region) const = 0;
};

// Lamé: a thick cylinder a <= r <= b about the z axis under internal pressure pa and external pb,
// plane strain (uz = 0): sigma_rr = A - B/r^2, sigma_tt = A + B/r^2, sigma_zz = 2 nu A,
// u_r = (1 + nu)/E ((1 - 2 nu) A r + B/r) (Timoshenko & Goodier, Theory of Elasticity, §28).
std::unique_ptr<ExactSolution> lame_cylinder(double a, double b, double pa, double pb, double E,
                                             double nu);

// Two Lamé cylinders shrunk or pressed together (SPEC §3.2.2): region 0 is a <= r <= c (E1, nu1,
// internal pressure pa), region 1 is c <= r <= b (E2, nu2, external pressure pb); the contact
// pressure makes u_r continuous at r = c. contact_pressure() gives it (3.294 for SPEC's data).
class CompoundCylinders;
std::unique_ptr<CompoundCylinders> compound_cylinders(double a, double c, double b, double pa,
                                                      double pb, double E1, double nu1, double E2,
                                                      double nu2);
class CompoundCylinders : public ExactSolution {
 public:
  virtual double contact_pressure() const = 0;
};

// A cantilever 0 <= x <= L of height h (z from 0 to h) and width b, loaded at x = L by a shear
// force P along +z distributed parabolically over the height, nu = 0: the plane-stress solution of
// Timoshenko & Goodier §21 is then the exact 3D solution (no lateral contraction, uy = 0):
// sigma_xx = -P (L - x) y / I, sigma_xz = P (c^2 - y^2) / (2 I), y = z - h/2, c = h/2,
// u_x = -P y (L x - x^2/2) / (E I) + P (c^2 y - y^3/3) / (E I), u_z = P (L x^2/2 - x^3/6) / (E I)
// (the neutral axis is clamped in position and slope at x = 0; tip deflection P L^3 / (3 E I)).
std::unique_ptr<ExactSolution> timoshenko_cantilever(double L, double h, double b, double P,
                                                     double E);

// A curved bar a <= r <= b, 0 <= theta <= 90 deg about z, thickness t, loaded at theta = 90 deg
// by a radial end force P (along +y there) through the shear stress of the exact solution, nu = 0
// (plane stress = 3D): Airy function (A r^3 + B/r + D r ln r) cos(theta) (Timoshenko & Goodier
// §31, turned by 90 deg), with the displacements integrated from the strains; the geometry of the
// MacNeal-Harder curved beam (a 4.12, b 4.32, t 0.1, E 1e7).
std::unique_ptr<ExactSolution> curved_bar(double a, double b, double t, double P, double E);

// Steady conduction through a cylinder wall r1 <= r <= r2 with T(r1) = T1, T(r2) = T2 (SPEC §6.2):
// T(r) = T1 - (T1 - T2) ln(r/r1) / ln(r2/r1).
std::unique_ptr<ExactSolution> cylinder_wall_heat(double r1, double r2, double T1, double T2,
                                                  double k);

}  // namespace styk::studies
