// Mechanics of the beam elements (beam.hpp): stiffness, thermal and line loads, section forces and
// the stresses at the section's extreme fibres, all from the generalised strains of
// beam_station.hpp integrated over the element's stations.
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "beam_station.hpp"
#include "styk/elements/beam.hpp"

namespace styk {
namespace {

using beam_detail::ElementSection;
using beam_detail::StationFrame;
using beam_detail::Vector6;

// alpha dT at every station (zero vector when no temperature changes), checking *EXPANSION.
std::vector<double> station_thermal_strains(const Material& material, const Eigen::VectorXd* dT,
                                            const std::vector<StationFrame>& frames) {
  std::vector<double> out(frames.size(), 0.0);
  if (dT == nullptr || dT->size() == 0 || dT->cwiseAbs().maxCoeff() == 0.0) return out;
  if (!material.expansion)
    throw InputError(material.where, "material " + material.name +
                                         ": *EXPANSION (thermal expansion coefficient) is "
                                         "required for a temperature change");
  for (std::size_t k = 0; k < frames.size(); ++k)
    out[k] = *material.expansion * frames[k].N.dot(*dT);
  return out;
}

// The element's section, the frames of its stations and their quadrature weights (x |dx/dxi|).
struct Stations {
  ElementSection section;
  std::vector<StationFrame> frames;
  std::vector<double> measure;  // Gauss weight times jacobian
};

Stations evaluate_stations(const Beam& beam, const ElementGeometry& g, const Material& material,
                           RuleKind kind) {
  if (g.X.rows() != beam.node_count() || g.X.cols() != 3)
    throw InputError(g.where, beam_detail::label(beam, g) + ": has " + std::to_string(g.X.rows()) +
                                  " nodes, expected " + std::to_string(beam.node_count()));
  Stations s;
  s.section = beam_detail::element_section(beam, g, material, beam.planar());
  std::vector<double> xi, weights;
  beam.stations(kind, xi, weights);
  s.frames.resize(xi.size());
  for (std::size_t k = 0; k < xi.size(); ++k) {
    beam_detail::station_frame(beam, g, s.section, xi[k], static_cast<int>(k) + 1, s.frames[k]);
    s.measure.push_back(weights[k] * s.frames[k].jacobian);
  }
  return s;
}

void check_displacements(const Beam& beam, const ElementGeometry& g,
                         const Eigen::Ref<const Eigen::VectorXd>& u) {
  if (u.size() != 6 * beam.node_count())
    throw std::invalid_argument(beam_detail::label(beam, g) + ": displacement vector has " +
                                std::to_string(u.size()) + " entries, expected " +
                                std::to_string(6 * beam.node_count()));
}

// Section forces and moments (SF1, SF2, SF3, SM1, SM2, SM3) at every station: the section
// stiffness times the generalised strains, less the thermal axial strain.
std::vector<Vector6> station_resultants(const Stations& s, const Material& material,
                                        const Eigen::Ref<const Eigen::VectorXd>& u,
                                        const Eigen::VectorXd* nodal_dT) {
  const std::vector<double> thermal = station_thermal_strains(material, nodal_dT, s.frames);
  std::vector<Vector6> out(s.frames.size());
  Eigen::MatrixXd B;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    beam_detail::strain_operator(s.frames[k], B);
    Vector6 e = B * u;
    e(0) -= thermal[k];
    out[k] = s.section.stiffness.cwiseProduct(e);
  }
  return out;
}

// Sets row `row` of a Tensor6-ordered matrix (11, 22, 33, 12, 13, 23) from a symmetric 3x3.
void put_tensor(const Eigen::Matrix3d& m, Eigen::MatrixXd& rows, Eigen::Index row) {
  rows.row(row) << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(0, 2), m(1, 2);
}

// Consistent nodal forces (translations only) of a force per unit length along the axis,
// force(frame, x) at the point x of a station frame, integrated with `points` Gauss points.
template <typename ForcePerLength>
void line_load(const Beam& beam, const ElementGeometry& g, int points, ForcePerLength&& force,
               Eigen::VectorXd& f) {
  if (g.section == nullptr || !g.section->beam)
    throw InputError(g.where, beam_detail::label(beam, g) + " has no *BEAM SECTION");
  ElementSection section;
  section.section = &*g.section->beam;
  section.direction = beam.planar() ? Vec3{0.0, 0.0, -1.0} : g.section->beam->direction;
  std::vector<double> xi, weights;
  gauss_legendre(points, xi, weights);
  f.setZero(6 * beam.node_count());
  StationFrame frame;
  for (std::size_t k = 0; k < xi.size(); ++k) {
    beam_detail::station_frame(beam, g, section, xi[k], static_cast<int>(k) + 1, frame);
    const Eigen::Vector3d x = g.X.transpose() * frame.N;
    const Eigen::Vector3d q = force(frame, x);
    for (int n = 0; n < beam.node_count(); ++n)
      f.segment<3>(6 * n) += (weights[k] * frame.jacobian * frame.N(n)) * q;
  }
}

}  // namespace

void Beam::stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                     Eigen::MatrixXd& K, const ElementOptions&) const {
  const Stations s = evaluate_stations(*this, g, material.material(), kind);
  K.setZero(6 * node_count(), 6 * node_count());
  Eigen::MatrixXd B;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    beam_detail::strain_operator(s.frames[k], B);
    K.noalias() += B.transpose() * (s.measure[k] * s.section.stiffness).asDiagonal() * B;
  }
  K = 0.5 * (K + K.transpose()).eval();
}

void Beam::eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material,
                            RuleKind kind, Eigen::VectorXd& f, const ElementOptions&,
                            const Eigen::MatrixXd* initial_stress) const {
  if (initial_stress != nullptr)
    throw InputError(g.where, beam_detail::label(*this, g) +
                                  ": *INITIAL CONDITIONS, TYPE=STRESS is not supported on beams");
  f.setZero(6 * node_count());
  if (!material.has_thermal_strain()) return;
  const Stations s = evaluate_stations(*this, g, material.material(), kind);
  const Eigen::VectorXd dT = material.temperature_change();
  const std::vector<double> thermal = station_thermal_strains(material.material(), &dT, s.frames);
  Eigen::MatrixXd B;
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    if (thermal[k] == 0.0) continue;
    beam_detail::strain_operator(s.frames[k], B);
    // f = B^T D e_th with e_th = (alpha dT, 0, ..., 0): the axial row only.
    f.noalias() += (s.measure[k] * s.section.stiffness(0) * thermal[k]) * B.row(0).transpose();
  }
}

void Beam::body_load(const ElementGeometry& g, double density, RuleKind,
                     const BodyAcceleration& acceleration, Eigen::VectorXd& f) const {
  if (g.section == nullptr || !g.section->beam)
    throw InputError(g.where, beam_detail::label(*this, g) + " has no *BEAM SECTION");
  // Mass per length density A; one Gauss point more than the nodes integrates the linear field
  // of a centrifugal load exactly on a straight element.
  const double mass = density * beam_section_properties(*g.section->beam).area;
  line_load(
      *this, g, node_count() + 1,
      [&](const StationFrame&, const Eigen::Vector3d& x) {
        const Vec3 a = acceleration.at({x(0), x(1), x(2)});
        return Eigen::Vector3d(mass * a[0], mass * a[1], mass * a[2]);
      },
      f);
}

void Beam::pressure_load(const ElementGeometry& g, int face, double p, Eigen::VectorXd& f) const {
  if (face < 0 || face > 1)
    throw InputError(g.where, beam_detail::label(*this, g) +
                                  " takes the load labels P1 and P2 "
                                  "(force per length along section "
                                  "axes 1 and 2), not P" +
                                  std::to_string(face + 1));
  if (planar_ && face == 0)
    throw InputError(g.where, beam_detail::label(*this, g) +
                                  " lies in the x-y plane: its section axis 1 is (0, 0, -1), out "
                                  "of the plane, so P1 has nothing to load; use P2 (along the "
                                  "in-plane normal n2)");
  // Gauss rule with as many points as nodes: exact for a uniform load on a straight element.
  line_load(
      *this, g, node_count(),
      [&](const StationFrame& frame, const Eigen::Vector3d&) -> Eigen::Vector3d {
        return p * (face == 0 ? frame.n1 : frame.n2);
      },
      f);
}

void Beam::section_resultants(const ElementGeometry& g, const ElementMaterial& material,
                              RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                              Eigen::MatrixXd& forces, Eigen::MatrixXd& moments) const {
  check_displacements(*this, g, u);
  const Stations s = evaluate_stations(*this, g, material.material(), kind);
  const Eigen::VectorXd dT = material.temperature_change();
  const std::vector<Vector6> r = station_resultants(s, material.material(), u, &dT);
  forces.resize(static_cast<Eigen::Index>(r.size()), 3);
  moments.resize(static_cast<Eigen::Index>(r.size()), 3);
  for (std::size_t k = 0; k < r.size(); ++k) {
    forces.row(static_cast<Eigen::Index>(k)) = r[k].head<3>().transpose();
    moments.row(static_cast<Eigen::Index>(k)) = r[k].tail<3>().transpose();
  }
}

void Beam::strains_stresses(const ElementGeometry& g, const ElementMaterial& material,
                            RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                            Eigen::MatrixXd& strain, Eigen::MatrixXd& stress, const ElementOptions&,
                            const Eigen::MatrixXd* initial_stress) const {
  if (initial_stress != nullptr)
    throw InputError(g.where, beam_detail::label(*this, g) +
                                  ": *INITIAL CONDITIONS, TYPE=STRESS is not supported on beams");
  check_displacements(*this, g, u);
  const Stations s = evaluate_stations(*this, g, material.material(), kind);
  const Eigen::VectorXd dT = material.temperature_change();
  const std::vector<Vector6> r = station_resultants(s, material.material(), u, &dT);
  const std::vector<double> thermal = station_thermal_strains(material.material(), &dT, s.frames);
  const BeamSectionProperties& p = s.section.properties;
  const double E = s.section.young, nu = s.section.poisson;
  const auto points = static_cast<Eigen::Index>(4 * r.size());
  stress.resize(points, 6);
  strain.resize(points, 6);
  for (std::size_t k = 0; k < r.size(); ++k) {
    const StationFrame& f = s.frames[k];
    const double N = r[k](0), M1 = r[k](3), M2 = r[k](4), T = r[k](5);
    for (int fibre = 0; fibre < 4; ++fibre) {
      const SectionPoint& x = p.fibres[fibre];
      const double axial = N / p.area + M1 * x[1] / p.I11 - M2 * x[0] / p.I22;
      const SectionPoint& tau = p.torsion_shear_per_torque[fibre];
      const Eigen::Vector3d shear = T * (tau[0] * f.n1 + tau[1] * f.n2);
      // sigma = axial t t^T + (t s^T + s t^T) with s the shear stress vector on the section.
      const Eigen::Matrix3d sigma =
          axial * f.t * f.t.transpose() + f.t * shear.transpose() + shear * f.t.transpose();
      // Isotropic compliance plus the thermal strain (tensor components).
      const Eigen::Matrix3d eps = (1.0 + nu) / E * sigma - (nu / E * sigma.trace() - thermal[k]) *
                                                               Eigen::Matrix3d::Identity();
      const Eigen::Index row = static_cast<Eigen::Index>(4 * k + fibre);
      put_tensor(sigma, stress, row);
      put_tensor(eps, strain, row);
    }
  }
}

}  // namespace styk
