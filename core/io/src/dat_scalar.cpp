// ccx 2.20 prints, for *HEAT TRANSFER:
//   " temperatures for set ALL and time  0.1000000E+01"       rows I10, 1P,1X,E13.6
//   " heat generation for set ALL and time ..."               (RFL) same rows
//   " total heat generation for set ALL and time ..."         (TOTALS=YES) 6X,1P,1X,E13.6
//   " heat flux (elem, integ.pnt.,qx,qy,qz) for setBLOCK and time ..."   I10,1X,I3,3(1X,E13.6)
// (no blank between "set" and the name in the heat-flux header: ccx's spelling, kept so the two
// reports diff clean). The electric blocks follow the same layout with their own names.
#include "dat_scalar.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "fortran_format.hpp"

namespace styk::io {
namespace {

std::string increment_label(const IncrementResult& inc) {
  return "step " + std::to_string(inc.step) + ", increment " + std::to_string(inc.increment);
}

void header(std::ostream& out, const std::string& what, const std::string& set, double time) {
  out << "\n " << what << set << " and time " << fortran_e14_7(time) << "\n\n";
}

void write_id(std::ostream& out, Id id) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%10" PRId64, static_cast<std::int64_t>(id));
  out << buffer;
}

std::vector<int> node_rows(const Model& model, const OutputRequest& request) {
  std::vector<int> nodes;
  if (request.set.empty()) {
    nodes.resize(model.node_ids.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = static_cast<int>(i);
  } else {
    const NodeSet* set = model.find_nset(request.set);
    if (set == nullptr)
      throw InputError(request.where, "*NODE PRINT: node set " + request.set + " is not defined");
    nodes = set->nodes;
  }
  std::sort(nodes.begin(), nodes.end(),
            [&](int a, int b) { return model.node_ids[a] < model.node_ids[b]; });
  return nodes;
}

std::vector<int> element_rows(const Model& model, const OutputRequest& request) {
  std::vector<int> elements;
  if (request.set.empty()) {
    elements.resize(model.elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i) elements[i] = static_cast<int>(i);
  } else {
    const ElementSet* set = model.find_elset(request.set);
    if (set == nullptr)
      throw InputError(request.where, "*EL PRINT: element set " + request.set + " is not defined");
    elements = set->elements;
  }
  std::sort(elements.begin(), elements.end(),
            [&](int a, int b) { return model.elements[a].id < model.elements[b].id; });
  return elements;
}

}  // namespace

void print_scalar(std::ostream& out, const Model& model, const OutputRequest& request,
                  const IncrementResult& inc) {
  const ScalarFieldResult& s = inc.scalar;
  const bool heat = s.kind == ScalarFieldResult::Kind::Temperature;
  const std::string set = request.set.empty() ? "ALL" : request.set;
  const bool nodal = request.kind == OutputRequest::Kind::NodePrint;
  for (const std::string& var : request.vars) {
    const bool value = var == (heat ? "NT" : "EPOT");
    const bool reaction = var == (heat ? "RFL" : "RECUR");
    const bool flux = var == (heat ? "HFL" : "ECD");
    if (!(nodal ? value || reaction : flux))
      throw InputError(request.where,
                       (nodal ? "*NODE PRINT" : "*EL PRINT") + std::string(": variable ") + var +
                           " does not belong to this step's field (it prints " +
                           (heat ? (nodal ? "NT, RFL" : "HFL") : (nodal ? "EPOT, RECUR" : "ECD")) +
                           ")");
    if (nodal) {
      const std::vector<double>& field = value ? s.value : s.reaction;
      if (field.size() != model.node_ids.size())
        throw std::runtime_error("*NODE PRINT asks for " + var + " but the results of " +
                                 increment_label(inc) + " hold no " + var + " for every node");
      const std::string what = value ? (heat ? "temperatures" : "electric potentials")
                                     : (heat ? "heat generation" : "electric currents");
      header(out, what + " for set ", set, inc.total_time);
      double total = 0.0;
      for (const int n : node_rows(model, request)) {
        write_id(out, model.node_ids[n]);
        out << ' ' << fortran_e13_6(field[n]) << '\n';
        total += field[n];
      }
      if (request.totals && reaction) {
        header(out, "total " + what + " for set ", set, inc.total_time);
        out << "       " << fortran_e13_6(total) << '\n';
      }
      continue;
    }
    if (inc.ip_offset.size() != model.elements.size() + 1 ||
        s.flux.size() != static_cast<std::size_t>(inc.ip_offset.back()))
      throw std::runtime_error("*EL PRINT asks for " + var + " but the results of " +
                               increment_label(inc) + " hold no " + var +
                               " at the integration points");
    header(out,
           heat ? "heat flux (elem, integ.pnt.,qx,qy,qz) for set"
                : "electric current density (elem, integ.pnt.,jx,jy,jz) for set",
           set, inc.total_time);
    for (const int e : element_rows(model, request))
      for (int p = inc.ip_offset[e]; p < inc.ip_offset[e + 1]; ++p) {
        write_id(out, model.elements[e].id);
        char point[16];
        std::snprintf(point, sizeof point, " %3d", p - inc.ip_offset[e] + 1);
        out << point;
        for (const double v : s.flux[p]) out << ' ' << fortran_e13_6(v);
        out << '\n';
      }
  }
}

}  // namespace styk::io
