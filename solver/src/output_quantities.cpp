#include "output_quantities.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "assembly.hpp"
#include "parallel.hpp"
#include "styk/core/output_requests.hpp"

namespace styk::solver_detail {
namespace {

bool asks(const std::vector<const OutputRequest*>& requests, const char* var) {
  for (const OutputRequest* r : requests)
    if (std::find(r->vars.begin(), r->vars.end(), var) != r->vars.end()) return true;
  return false;
}

Vector6d voigt(const Tensor6& t) {
  Vector6d v;
  for (int c = 0; c < 6; ++c) v(c) = t[c];
  return v;
}

// The estimate compares the continuum stress at the element's integration points (of the rule
// its section chose) with the smoothed nodal stress. Beams and shells store section stations and
// fibres instead (their S and laws do not line up with the rule's points: reading them as such
// gave NaN or garbage), so they get no estimate.
bool continuum_with_point_output(const TElement& element, const PreparedModel& prepared, int e) {
  const ElementForm form = element.form();
  if (form == ElementForm::Line || form == ElementForm::Shell) return false;
  return prepared.ip_offset[e + 1] - prepared.ip_offset[e] ==
         element.rule(prepared.rule_kind[e]).size();
}

}  // namespace

OutputNeeds output_needs(const Model& model, std::size_t step) {
  OutputNeeds needs;
  const auto prints = effective_requests(model, step, OutputRequest::Kind::ElementPrint);
  const auto files = effective_requests(model, step, OutputRequest::Kind::ElementFile);
  needs.energies =
      asks(prints, "ENER") || asks(prints, "ELSE") || asks(prints, "EVOL") || asks(files, "ENER");
  needs.thermal_strains = asks(files, "THE");
  // CalculiX: S on *EL FILE brings ERR along unless NOE is asked for too.
  needs.error_estimate = asks(files, "ERR") || (asks(files, "S") && !asks(files, "NOE"));
  return needs;
}

void estimate_stress_errors(const Model& model, const PreparedModel& prepared,
                            const ElementStates& states, int threads, IncrementResult& out) {
  const int elements = model.element_count();
  std::vector<double> error2(elements, 0.0), energy2(elements, 0.0);
  parallel_for(elements, resolve_threads(threads), 16, [&](int begin, int end, int) {
    ElementGeometry g;
    Eigen::VectorXd dv, N;
    Eigen::MatrixXd dN;
    std::vector<MaterialPoint> laws;
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      if (!continuum_with_point_output(element, prepared, e)) continue;  // ERR stays 0
      element_geometry(model, prepared, e, g);
      const RuleKind kind = prepared.rule_kind[e];  // the rule its stresses are output at
      element.point_volumes(g, kind, dv);
      element.point_laws(g, states.law(e), kind, laws);
      const IntegrationRule rule = element.rule(kind);
      const int n = element.node_count();
      N.resize(n);
      dN.resize(n, 3);
      const int* nodes = model.element_nodes(e);
      const int first = prepared.ip_offset[e];
      for (int k = 0; k < rule.size(); ++k) {
        element.der(rule.points[k], N, dN);
        Vector6d smoothed = Vector6d::Zero();
        for (int a = 0; a < n; ++a) smoothed += N(a) * voigt(out.S_nodal_I[nodes[a]]);
        const Vector6d own = voigt(out.S[first + k]);
        // D maps engineering strains to stresses, so C = D^-1 maps the stress (tensor shear
        // components) to engineering strains and s . C s is twice the energy density.
        const Matrix6d compliance = laws[k].D.inverse();
        const Vector6d difference = smoothed - own;
        error2[e] += dv(k) * difference.dot(compliance * difference);
        energy2[e] += dv(k) * own.dot(compliance * own);
      }
    }
  });
  double total_error = 0.0, total_energy = 0.0;
  for (int e = 0; e < elements; ++e) {
    total_error += error2[e];
    total_energy += energy2[e];
  }
  const double mean = std::sqrt((total_energy + total_error) / std::max(1, elements));
  out.ERR.assign(elements, 0.0);
  if (!(mean > 0.0)) return;
  for (int e = 0; e < elements; ++e) out.ERR[e] = 100.0 * std::sqrt(error2[e]) / mean;
}

void compute_section_forces(const Model& model, const PreparedModel& prepared, std::size_t step,
                            IncrementResult& out) {
  out.sections.clear();
  for (const OutputRequest* request :
       effective_requests(model, step, OutputRequest::Kind::SectionPrint)) {
    const Surface& surface = model.surfaces.at(request->set);
    SectionForces section;
    section.surface = request->set;
    section.name = request->name;
    Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    double area = 0.0;
    ElementGeometry g;
    std::vector<Vec3> points;
    std::vector<Eigen::Vector3d> weighted;
    for (const SurfaceFace& sf : surface.faces) {
      const TElement& element = *prepared.formulation[sf.element];
      element_geometry(model, prepared, sf.element, g);
      const FaceDef& face = element.faces()[sf.face - 1];
      element.face_quadrature(g, face, points, weighted);
      const double outward = face.value > 0.0 ? 1.0 : -1.0;
      const int n = element.node_count();
      Eigen::VectorXd N(n);
      Eigen::MatrixXd dN(n, 3);
      const int* nodes = model.element_nodes(sf.element);
      for (std::size_t k = 0; k < points.size(); ++k) {
        element.der(points[k], N, dN);
        Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
        for (int a = 0; a < n; ++a) {
          const Tensor6& s = out.S_nodal_I[nodes[a]];
          Eigen::Matrix3d t;
          t << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
          sigma += N(a) * t;
        }
        const Eigen::Vector3d dA = outward * weighted[k];  // out of the element
        const Eigen::Vector3d x = g.X.transpose() * N;
        const Eigen::Vector3d traction = sigma * dA;
        F += traction;
        M += x.cross(traction);
        area += dA.norm();
        centre += dA.norm() * x;
        normal += dA;
      }
    }
    if (area > 0.0) centre /= area;
    if (normal.norm() > 0.0) normal.normalize();
    const Eigen::Vector3d Mc = M - centre.cross(F);
    auto put = [](Vec3& to, const Eigen::Vector3d& from) { to = {from[0], from[1], from[2]}; };
    put(section.force, F);
    put(section.moment, M);
    put(section.centre, centre);
    put(section.normal, normal);
    put(section.moment_about_centre, Mc);
    section.area = area;
    section.normal_force = F.dot(normal);
    section.shear_force = (F - section.normal_force * normal).norm();
    section.torque = Mc.dot(normal);
    section.bending_moment = (Mc - section.torque * normal).norm();
    out.sections.push_back(std::move(section));
  }
}

}  // namespace styk::solver_detail
