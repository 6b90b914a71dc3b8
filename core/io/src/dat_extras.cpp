#include "dat_extras.hpp"

#include <cinttypes>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "fortran_format.hpp"

namespace styk::io {
namespace {

void header(std::ostream& out, const std::string& what, const std::string& set, double time) {
  out << "\n " << what << " for set " << set << " and time " << fortran_e14_7(time) << "\n\n";
}

void id_column(std::ostream& out, Id id) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%10" PRId64, static_cast<std::int64_t>(id));
  out << buffer;
}

// omega^2 of the CENTRIF load on each element in step `step` (0-based), as accumulated over the
// steps (OP=NEW resets, a later load replaces an earlier one).
std::map<int, double> centrifugal_loads(const Model& model, std::size_t step) {
  std::map<int, double> omega2;
  for (std::size_t k = 0; k <= step && k < model.steps.size(); ++k) {
    if (model.steps[k].dload_op_new) omega2.clear();
    for (const BodyLoad& b : model.steps[k].body_loads)
      if (b.kind == BodyLoad::Kind::Centrifugal) omega2[b.element] = b.magnitude;
  }
  return omega2;
}

const std::vector<double>& element_field(const IncrementResult& inc, const std::string& var,
                                         std::size_t elements) {
  const std::vector<double>& field = var == "ELSE" ? inc.element_energy : inc.element_volume;
  if (field.size() != elements)
    throw std::runtime_error("*EL PRINT asks for " + var + " but the results of step " +
                             std::to_string(inc.step) + " hold none");
  return field;
}

void values_line(std::ostream& out, std::initializer_list<double> values) {
  out << "   ";
  bool first = true;
  for (double v : values) {
    out << (first ? "" : " ") << fortran_e13_6(v);
    first = false;
  }
  out << '\n';
}

}  // namespace

bool is_element_extra(const std::string& var) {
  return var == "ENER" || var == "ELSE" || var == "EVOL" || var == "CENT";
}

void print_element_extra(std::ostream& out, const Model& model, const OutputRequest& request,
                         const std::string& var, const std::string& set,
                         const std::vector<int>& elements, const IncrementResult& inc) {
  if (var == "ENER") {
    if (inc.ENER.size() !=
            static_cast<std::size_t>(inc.ip_offset.empty() ? 0 : inc.ip_offset.back()) ||
        inc.ENER.empty())
      throw std::runtime_error("*EL PRINT asks for ENER but the results of step " +
                               std::to_string(inc.step) + " hold none");
    if (request.totals_only) return;  // a point variable has no total
    header(out, "internal energy density (elem, integ.pnt.,energy)", set, inc.total_time);
    for (int e : elements)
      for (int p = inc.ip_offset[e]; p < inc.ip_offset[e + 1]; ++p) {
        id_column(out, model.elements[e].id);
        char point[16];
        std::snprintf(point, sizeof point, " %3d", p - inc.ip_offset[e] + 1);
        out << point << ' ' << fortran_e13_6(inc.ENER[p]) << '\n';
      }
    return;
  }
  if (var == "CENT") {
    if (request.totals_only) return;
    const std::map<int, double> omega2 = centrifugal_loads(model, inc.step - 1);
    header(out, "centrifugal force(element,omega square)", set, inc.total_time);
    for (int e : elements) {
      const auto it = omega2.find(e);
      id_column(out, model.elements[e].id);
      out << ' ' << fortran_e13_6(it == omega2.end() ? 0.0 : it->second) << '\n';
    }
    return;
  }
  const std::vector<double>& field = element_field(inc, var, model.elements.size());
  const bool energy = var == "ELSE";
  double total = 0.0;
  for (int e : elements) total += field[e];
  if (!request.totals_only) {
    header(out, energy ? "internal energy (element, energy)" : "volume (element, volume)", set,
           inc.total_time);
    for (int e : elements) {
      id_column(out, model.elements[e].id);
      out << ' ' << fortran_e13_6(field[e]) << '\n';
    }
  }
  if (request.totals) {
    header(out, energy ? "total internal energy" : "total volume", set, inc.total_time);
    out << "       " << fortran_e13_6(total) << '\n';
  }
}

void print_section(std::ostream& out, const OutputRequest& request, const IncrementResult& inc) {
  const SectionForces* found = nullptr;
  for (const SectionForces& s : inc.sections)
    if (s.surface == request.set && s.name == request.name) found = &s;
  if (!found)
    throw std::runtime_error("*SECTION PRINT, SURFACE=" + request.set +
                             " has no section forces in the results of step " +
                             std::to_string(inc.step));
  const SectionForces& s = *found;
  out << "\n\n\n statistics for surface set " << s.surface << " and time "
      << fortran_e14_7(inc.total_time) << "\n\n";
  out << "   total surface force (fx,fy,fz) and moment about the origin(mx,my,mz)\n\n";
  values_line(out, {s.force[0], s.force[1], s.force[2], s.moment[0], s.moment[1], s.moment[2]});
  out << "\n   center of gravity and mean normal\n\n";
  values_line(out, {s.centre[0], s.centre[1], s.centre[2], s.normal[0], s.normal[1], s.normal[2]});
  out << "\n   moment about the center of gravity(mx,my,mz)\n\n";
  values_line(out, {s.moment_about_centre[0], s.moment_about_centre[1], s.moment_about_centre[2]});
  out << "\n   area, normal force (+ = tension), shear force (size), torque and bending moment "
         "(size)\n\n";
  values_line(out, {s.area, s.normal_force, s.shear_force, s.torque, s.bending_moment});
}

}  // namespace styk::io
