// The linear elastic law of a material at a point: what *ELASTIC, *EXPANSION and the section's
// *ORIENTATION say, evaluated at a temperature and a position. Elements never see the material's
// constants: their DEE hook receives the 3D law of the point (MaterialPoint) and specialises it
// to their kinematics (plane stress, truss).
//
// Conventions (CalculiX/Abaqus): Voigt order 11, 22, 33, 12, 13, 23 with engineering shear
// strains, so D(i, j) are the tensor constants D_ijkl of the deck (D(3, 3) = D1212, D(0, 3) =
// D1112). Table rows are interpolated linearly in temperature and held constant beyond the first
// and last rows. The thermal strain is the secant form alpha(T) (T - Z) - alpha(T0) (T0 - Z),
// Z = *EXPANSION, ZERO=, T0 the initial temperature.
#pragma once

#include <Eigen/Core>

#include "styk/core/model.hpp"

namespace styk {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// The material at one point, in global axes.
struct MaterialPoint {
  Matrix6d D = Matrix6d::Zero();               // 3D stiffness, engineering shear
  Vector6d thermal_strain = Vector6d::Zero();  // engineering shear components
  // Isotropic elasticity (then young/poisson are its constants) and isotropic expansion: what
  // elements that cannot take a direction-dependent law (trusses) check.
  bool isotropic = true;
  bool isotropic_expansion = true;
  double young = 0.0;
  double poisson = 0.0;
  double temperature = 0.0;  // where the law was evaluated
};

// Throws InputError at the material's line when its elastic data do not define a law: E <= 0 or
// nu outside (-1, 0.5), engineering constants that are not positive, or a stiffness that is not
// positive definite at some temperature of its table.
void check_elasticity(const Material& material);

// The 3D stiffness in the material axes at temperature T. `isotropic`, when not null, receives
// whether the law is isotropic, with its constants in young/poisson.
Matrix6d material_stiffness(const Material& material, double temperature, bool* isotropic = nullptr,
                            double* young = nullptr, double* poisson = nullptr);

// The law of `material` at temperature T in its own axes, with no thermal strain: what a caller
// without positions or temperatures hands to an element's DEE hook. Throws like
// material_stiffness().
MaterialPoint material_point(const Material& material, double temperature = 0.0);

// The thermal strain (engineering shear) in the material axes between the initial temperature T0
// and T; zero when T == T0. Throws InputError at the material when T != T0 and it has no
// *EXPANSION.
Vector6d material_thermal_strain(const Material& material, double temperature,
                                 double initial_temperature);

// Voigt transformations for material axes R = [e1 e2 e3] (unit columns, global components):
// the stiffness D_global = T^T D_local T, and a strain (engineering shear) from local to global.
Matrix6d stiffness_to_global(const Matrix6d& local, const Eigen::Matrix3d& R);
Vector6d strain_to_global(const Vector6d& local, const Eigen::Matrix3d& R);

// The law of one element at its points: the material, the material axes of its section (may be
// null: global axes) and the temperatures at its nodes now and initially (may be empty: the
// law at temperature 0 and no thermal strain). Implicitly built from a Material for the common
// constant case. Cheap to copy; it refers to, and does not own, the material and the axes.
class ElementMaterial {
 public:
  ElementMaterial(const Material& material);  // NOLINT(google-explicit-constructor)
  ElementMaterial(const Material& material, const LocalAxes* axes, Eigen::VectorXd temperature,
                  Eigen::VectorXd initial_temperature);

  const Material& material() const { return *material_; }
  // The law differs between the points of the element (temperature table over a non-uniform
  // temperature, or cylindrical material axes): evaluate it at every point.
  bool varies() const { return varies_; }
  // Some point may have a thermal strain (the temperatures differ from the initial ones).
  bool has_thermal_strain() const { return thermal_; }
  // T - T_initial at the element's nodes (empty without temperatures): what structural elements,
  // which take a constant expansion coefficient, strain with.
  Eigen::VectorXd temperature_change() const;

  // The law at the point with shape functions N (element nodes) and global position x.
  void at(const Eigen::Ref<const Eigen::VectorXd>& N, const Eigen::Vector3d& x,
          MaterialPoint& point) const;

 private:
  const Material* material_;
  const LocalAxes* axes_ = nullptr;
  Eigen::VectorXd temperature_, initial_temperature_;
  bool varies_ = false;
  bool thermal_ = false;
};

}  // namespace styk
