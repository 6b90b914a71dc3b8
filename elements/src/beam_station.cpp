#include "beam_station.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

namespace styk::beam_detail {
namespace {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string vector_text(const Vec3& v) {
  return "(" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + ")";
}

void check_planar(const TElement& element, const ElementGeometry& g, const Section& section) {
  const BeamSection& beam = *section.beam;
  if (beam.direction_given) {
    const Vec3& d = beam.direction;
    if (std::abs(d[0]) > 1e-12 * std::abs(d[2]) || std::abs(d[1]) > 1e-12 * std::abs(d[2]) ||
        !(d[2] < 0.0))
      throw InputError(section.where,
                       "*BEAM SECTION of element set " + section.elset + ": element " +
                           std::to_string(g.id) + " is a planar beam (" + element.name() +
                           "), whose first section axis is always (0, 0, -1); the data line "
                           "gives " +
                           vector_text(d));
  }
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  for (Eigen::Index k = 1; k < g.X.rows(); ++k)
    if (std::abs(g.X(k, 2) - g.X(0, 2)) > 1e-9 * scale)
      throw InputError(g.where, label(element, g) +
                                    " is a planar beam, but its nodes do not share one z: it "
                                    "must lie in a plane parallel to x-y (use B31/B32 in space)");
}

}  // namespace

std::string label(const TElement& element, const ElementGeometry& g) {
  return "element " + std::to_string(g.id) + " (" + element.name() + ")";
}

ElementSection element_section(const TElement& element, const ElementGeometry& g,
                               const Material& material, bool planar) {
  if (g.section == nullptr || !g.section->beam)
    throw InputError(g.where, label(element, g) + " has no *BEAM SECTION");
  const Section& section = *g.section;
  if (const std::string why = check_beam_section(*section.beam); !why.empty())
    throw InputError(section.where, "*BEAM SECTION of element set " + section.elset + ": " + why);
  check_elasticity(material);  // E and nu given and admissible, with the material's line
  if (planar) check_planar(element, g, section);

  ElementSection out;
  out.section = &*section.beam;
  out.properties = beam_section_properties(*section.beam);
  out.young = *material.young;
  out.poisson = *material.poisson;
  out.shear_modulus = out.young / (2.0 * (1.0 + out.poisson));
  out.direction = planar ? Vec3{0.0, 0.0, -1.0} : section.beam->direction;
  const BeamSectionProperties& p = out.properties;
  const double E = out.young, G = out.shear_modulus;
  out.stiffness << E * p.area, G * p.shear_area2, G * p.shear_area1, E * p.I11, E * p.I22, G * p.J;
  if (planar) out.stiffness(2) = out.stiffness(4) = out.stiffness(5) = 0.0;
  return out;
}

void station_frame(const TElement& element, const ElementGeometry& g, const ElementSection& s,
                   double xi, int point, StationFrame& frame) {
  const int n = element.node_count();
  frame.N.resize(n);
  Eigen::MatrixXd dN(n, 3);
  element.der({xi, 0.0, 0.0}, frame.N, dN);
  const Eigen::Vector3d tangent = g.X.transpose() * dN.col(0);
  frame.jacobian = tangent.norm();
  const double scale = std::max(g.X.cwiseAbs().maxCoeff(), 1e-300);
  if (!(frame.jacobian > 1e-12 * scale))
    throw InputError(g.where, label(element, g) + ": zero length at station " +
                                  std::to_string(point) + " (its nodes coincide)");
  frame.t = tangent / frame.jacobian;
  frame.dNds = dN.col(0) / frame.jacobian;
  Vec3 n1, n2;
  if (!beam_section_axes({frame.t.x(), frame.t.y(), frame.t.z()}, s.direction, n1, n2))
    throw InputError(g.section->where,
                     "*BEAM SECTION of element set " + g.section->elset +
                         ": the first section axis " + vector_text(s.direction) +
                         (s.section->direction_given ? "" : " (the default)") +
                         " is parallel to the axis of element " + std::to_string(g.id) +
                         "; give a direction across the beam on the second data line");
  frame.n1 = Eigen::Vector3d(n1[0], n1[1], n1[2]);
  frame.n2 = Eigen::Vector3d(n2[0], n2[1], n2[2]);
}

void strain_operator(const StationFrame& f, Eigen::MatrixXd& B) {
  const Eigen::Index n = f.N.size();
  B.setZero(6, 6 * n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index u = 6 * k, r = 6 * k + 3;
    const double dN = f.dNds(k), N = f.N(k);
    B.block<1, 3>(0, u) = dN * f.t.transpose();   // eps    = t . u'
    B.block<1, 3>(1, u) = dN * f.n2.transpose();  // gamma2 = n2 . u' + n1 . theta
    B.block<1, 3>(1, r) = N * f.n1.transpose();
    B.block<1, 3>(2, u) = dN * f.n1.transpose();  // gamma1 = n1 . u' - n2 . theta
    B.block<1, 3>(2, r) = -N * f.n2.transpose();
    B.block<1, 3>(3, r) = dN * f.n1.transpose();  // kappa1 = n1 . theta'
    B.block<1, 3>(4, r) = dN * f.n2.transpose();  // kappa2 = n2 . theta'
    B.block<1, 3>(5, r) = dN * f.t.transpose();   // phi'   = t . theta'
  }
}

}  // namespace styk::beam_detail
