#include "styk/core/constitutive.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Dense>

#include "styk/core/local_axes.hpp"

namespace styk {
namespace {

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

[[noreturn]] void fail(const Material& m, const std::string& what) {
  throw InputError(m.where, "material " + m.name + ": " + what);
}

// The constants of a table at temperature T: linear between rows, the end rows beyond them.
std::vector<double> interpolate(const std::vector<MaterialTableRow>& table, double T) {
  if (T <= table.front().temperature) return table.front().values;
  if (T >= table.back().temperature) return table.back().values;
  std::size_t upper = 1;
  while (table[upper].temperature < T) ++upper;
  const MaterialTableRow& a = table[upper - 1];
  const MaterialTableRow& b = table[upper];
  const double t = (T - a.temperature) / (b.temperature - a.temperature);
  std::vector<double> out(a.values.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = (1.0 - t) * a.values[i] + t * b.values[i];
  return out;
}

Matrix6d isotropic(double E, double nu) {
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu = E / (2.0 * (1.0 + nu));
  Matrix6d D = Matrix6d::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  D.topLeftCorner<3, 3>().diagonal().array() += 2.0 * mu;
  D.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  return D;
}

// D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323.
Matrix6d orthotropic(const std::vector<double>& c) {
  Matrix6d D = Matrix6d::Zero();
  D(0, 0) = c[0];
  D(0, 1) = D(1, 0) = c[1];
  D(1, 1) = c[2];
  D(0, 2) = D(2, 0) = c[3];
  D(1, 2) = D(2, 1) = c[4];
  D(2, 2) = c[5];
  D(3, 3) = c[6];
  D(4, 4) = c[7];
  D(5, 5) = c[8];
  return D;
}

// E1, E2, E3, nu12, nu13, nu23, G12, G13, G23: the inverse of the compliance.
Matrix6d engineering(const std::vector<double>& c) {
  const double E1 = c[0], E2 = c[1], E3 = c[2], nu12 = c[3], nu13 = c[4], nu23 = c[5];
  Matrix6d S = Matrix6d::Zero();
  S(0, 0) = 1.0 / E1;
  S(1, 1) = 1.0 / E2;
  S(2, 2) = 1.0 / E3;
  S(0, 1) = S(1, 0) = -nu12 / E1;
  S(0, 2) = S(2, 0) = -nu13 / E1;
  S(1, 2) = S(2, 1) = -nu23 / E2;
  S(3, 3) = 1.0 / c[6];
  S(4, 4) = 1.0 / c[7];
  S(5, 5) = 1.0 / c[8];
  return S.inverse();
}

// The 21 constants in the CalculiX/Abaqus order: the upper triangle column by column in Voigt
// order 11, 22, 33, 12, 13, 23 (D1111; D1122, D2222; D1133, D2233, D3333; D1112, ...).
Matrix6d anisotropic(const std::vector<double>& c) {
  Matrix6d D;
  std::size_t k = 0;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i <= j; ++i) D(i, j) = D(j, i) = c[k++];
  return D;
}

Matrix6d stiffness_of(ElasticType type, const std::vector<double>& c) {
  switch (type) {
    case ElasticType::Isotropic:
      return isotropic(c[0], c[1]);
    case ElasticType::Orthotropic:
      return orthotropic(c);
    case ElasticType::EngineeringConstants:
      return engineering(c);
    case ElasticType::Anisotropic:
      return anisotropic(c);
  }
  return Matrix6d::Zero();
}

void check_isotropic(const Material& m, double E, double nu) {
  if (!(E > 0.0) || !std::isfinite(E))
    fail(m, "Young's modulus must be positive, read " + format_number(E));
  if (!(nu > -1.0 && nu < 0.5))
    fail(m, "Poisson's ratio must lie in (-1, 0.5), read " + format_number(nu));
}

void check_row(const Material& m, const MaterialTableRow& row) {
  const std::string at =
      m.elastic_table.size() > 1 ? " at temperature " + format_number(row.temperature) : "";
  if (m.elastic_type == ElasticType::Isotropic) {
    check_isotropic(m, row.values[0], row.values[1]);
    return;
  }
  if (m.elastic_type == ElasticType::EngineeringConstants) {
    const char* names[] = {"E1", "E2", "E3", "nu12", "nu13", "nu23", "G12", "G13", "G23"};
    for (int i : {0, 1, 2, 6, 7, 8})
      if (!(row.values[i] > 0.0))
        fail(m, std::string(names[i]) + " = " + format_number(row.values[i]) + at +
                    " must be positive");
  }
  // Positive definite: the strain energy of every strain is positive.
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(stiffness_of(m.elastic_type, row.values));
  if (!(eigen.eigenvalues().minCoeff() > 1e-12 * eigen.eigenvalues().cwiseAbs().maxCoeff()))
    fail(m, "the elastic constants" + at +
                " do not give a positive definite stiffness (smallest eigenvalue " +
                format_number(eigen.eigenvalues().minCoeff()) + ")");
}

// The thermal expansion tensor (engineering Voigt vector of alpha_ij) at temperature T.
Vector6d expansion_at(const Material& m, double T) {
  Vector6d alpha = Vector6d::Zero();
  if (m.expansion) {
    alpha.head<3>().setConstant(*m.expansion);
    return alpha;
  }
  const std::vector<double> c = interpolate(m.expansion_table, T);
  switch (m.expansion_type) {
    case ExpansionType::Isotropic:
      alpha.head<3>().setConstant(c[0]);
      break;
    case ExpansionType::Orthotropic:
      alpha.head<3>() << c[0], c[1], c[2];
      break;
    case ExpansionType::Anisotropic:
      alpha << c[0], c[1], c[2], 2.0 * c[3], 2.0 * c[4], 2.0 * c[5];
      break;
  }
  return alpha;
}

// Engineering Voigt vector <-> symmetric tensor.
Eigen::Matrix3d tensor_of(const Vector6d& v) {
  Eigen::Matrix3d t;
  t << v(0), 0.5 * v(3), 0.5 * v(4), 0.5 * v(3), v(1), 0.5 * v(5), 0.5 * v(4), 0.5 * v(5), v(2);
  return t;
}
Vector6d voigt_of(const Eigen::Matrix3d& t) {
  Vector6d v;
  v << t(0, 0), t(1, 1), t(2, 2), 2.0 * t(0, 1), 2.0 * t(0, 2), 2.0 * t(1, 2);
  return v;
}

}  // namespace

void check_elasticity(const Material& material) {
  if (material.young && material.poisson) {
    check_isotropic(material, *material.young, *material.poisson);
    return;
  }
  if (material.elastic_table.empty()) fail(material, "*ELASTIC (the elastic constants) is missing");
  for (const MaterialTableRow& row : material.elastic_table) check_row(material, row);
}

Matrix6d material_stiffness(const Material& material, double temperature, bool* isotropic_law,
                            double* young, double* poisson) {
  double E = 0.0, nu = 0.0;
  Matrix6d D;
  bool iso = material.elastic_type == ElasticType::Isotropic;
  if (material.young && material.poisson) {
    E = *material.young;
    nu = *material.poisson;
    check_isotropic(material, E, nu);  // two comparisons: every caller gets the check
    iso = true;
    D = isotropic(E, nu);
  } else {
    if (material.elastic_table.empty())
      fail(material, "*ELASTIC (the elastic constants) is missing");
    const std::vector<double> c = interpolate(material.elastic_table, temperature);
    if (iso) {
      E = c[0];
      nu = c[1];
    }
    D = stiffness_of(material.elastic_type, c);
  }
  if (isotropic_law) *isotropic_law = iso;
  if (young) *young = E;
  if (poisson) *poisson = nu;
  return D;
}

MaterialPoint material_point(const Material& material, double temperature) {
  MaterialPoint point;
  point.temperature = temperature;
  point.D =
      material_stiffness(material, temperature, &point.isotropic, &point.young, &point.poisson);
  point.isotropic_expansion =
      material.expansion.has_value() || material.expansion_type == ExpansionType::Isotropic;
  return point;
}

Vector6d material_thermal_strain(const Material& material, double temperature,
                                 double initial_temperature) {
  if (temperature == initial_temperature) return Vector6d::Zero();
  if (!material.has_expansion())
    fail(material,
         "*EXPANSION (thermal expansion coefficient) is required for a temperature "
         "change");
  const double zero = material.expansion_reference;
  return expansion_at(material, temperature) * (temperature - zero) -
         expansion_at(material, initial_temperature) * (initial_temperature - zero);
}

Matrix6d stiffness_to_global(const Matrix6d& local, const Eigen::Matrix3d& R) {
  // T maps a global engineering strain to the local one (eps_local = R^T eps_global R); the
  // energy sigma . eps is the same in both systems, so D_global = T^T D_local T.
  Matrix6d T;
  for (int q = 0; q < 6; ++q) T.col(q) = voigt_of(R.transpose() * tensor_of(Vector6d::Unit(q)) * R);
  return T.transpose() * local * T;
}

Vector6d strain_to_global(const Vector6d& local, const Eigen::Matrix3d& R) {
  return voigt_of(R * tensor_of(local) * R.transpose());
}

ElementMaterial::ElementMaterial(const Material& material) : material_(&material) {
  varies_ = false;
  thermal_ = false;
}

ElementMaterial::ElementMaterial(const Material& material, const LocalAxes* axes,
                                 Eigen::VectorXd temperature, Eigen::VectorXd initial_temperature)
    : material_(&material),
      axes_(axes),
      temperature_(std::move(temperature)),
      initial_temperature_(std::move(initial_temperature)) {
  if (initial_temperature_.size() == 0 && temperature_.size() > 0)
    initial_temperature_ = Eigen::VectorXd::Zero(temperature_.size());
  if (temperature_.size() == 0 && initial_temperature_.size() > 0)
    temperature_ = initial_temperature_;
  const bool uniform_temperature =
      temperature_.size() == 0 || temperature_.maxCoeff() == temperature_.minCoeff();
  const bool tabulated = material.elastic_table.size() > 1 || material.expansion_table.size() > 1;
  const bool cylindrical = axes_ && axes_->system == CoordinateSystem::Cylindrical;
  thermal_ = temperature_.size() > 0 && temperature_ != initial_temperature_;
  varies_ = cylindrical || (tabulated && !uniform_temperature) ||
            (thermal_ && (temperature_ - initial_temperature_).maxCoeff() !=
                             (temperature_ - initial_temperature_).minCoeff());
}

Eigen::VectorXd ElementMaterial::temperature_change() const {
  if (!thermal_) return {};
  return temperature_ - initial_temperature_;
}

void ElementMaterial::at(const Eigen::Ref<const Eigen::VectorXd>& N, const Eigen::Vector3d& x,
                         MaterialPoint& point) const {
  const Material& m = *material_;
  const double T = temperature_.size() > 0 ? N.dot(temperature_) : 0.0;
  const double T0 = initial_temperature_.size() > 0 ? N.dot(initial_temperature_) : 0.0;
  point.temperature = T;
  point.D = material_stiffness(m, T, &point.isotropic, &point.young, &point.poisson);
  point.isotropic_expansion =
      m.expansion.has_value() || m.expansion_type == ExpansionType::Isotropic;
  point.thermal_strain = thermal_ ? material_thermal_strain(m, T, T0) : Vector6d::Zero();
  if (!axes_) return;
  Eigen::Matrix3d R;
  const Vec3 at{x(0), x(1), x(2)};
  if (!local_axes_at(*axes_, at, R))
    fail(m, "its material axes (*ORIENTATION) are undefined at point (" + format_number(x(0)) +
                ", " + format_number(x(1)) + ", " + format_number(x(2)) +
                "), which lies on the axis of the cylindrical system");
  if (!point.isotropic) point.D = stiffness_to_global(point.D, R);
  if (!point.isotropic_expansion) point.thermal_strain = strain_to_global(point.thermal_strain, R);
}

}  // namespace styk
