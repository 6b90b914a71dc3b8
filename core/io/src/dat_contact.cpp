#include "dat_contact.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fortran_format.hpp"

namespace styk::io {
namespace {

// ccx's contact blocks put the E14.7 time right after "time" (one blank, the field's own), unlike
// its "for set" blocks ("time  0.1000000E+01"); checked against ccx in contact_print_test.cpp.
void header(std::ostream& out, const std::string& what, double time) {
  out << "\n " << what << " and time" << fortran_e14_7(time) << "\n\n";
}

void row(std::ostream& out, Id id, std::initializer_list<double> values) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%10" PRId64, static_cast<std::int64_t>(id));
  out << buffer;
  for (const double v : values) out << ' ' << fortran_e13_6(v);
  out << '\n';
}

void vector_row(std::ostream& out, const char* label, const Vec3& v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%10s", label);
  out << buffer;
  for (const double x : v) out << ' ' << fortran_e13_6(x);
  out << '\n';
}

// The normal law of a pair (Styk-only line): "exact (hard)" or the penalty law and its slope.
void law_row(std::ostream& out, const Model& model, const ContactPair& pair) {
  out << "       law ";
  const auto it = model.surface_interactions.find(pair.interaction);
  const PressureOverclosure behavior =
      it == model.surface_interactions.end() ? PressureOverclosure{} : it->second.behavior;
  switch (behavior.law) {
    case PressureOverclosure::Law::Hard:
      out << "exact (hard)\n";
      return;
    case PressureOverclosure::Law::Linear:
      out << "penalty LINEAR K=" << fortran_e13_6(behavior.slope) << '\n';
      return;
    case PressureOverclosure::Law::Tied:
      out << "penalty TIED K=" << fortran_e13_6(behavior.slope) << '\n';
      return;
    case PressureOverclosure::Law::Exponential:
      out << "penalty EXPONENTIAL c0=" << fortran_e13_6(behavior.c0.value_or(0.0))
          << " p0=" << fortran_e13_6(behavior.p0) << '\n';
      return;
  }
}

}  // namespace

void print_contact(std::ostream& out, const Model& model, const OutputRequest& request,
                   const IncrementResult& inc) {
  // Rows by slave node id, as ccx sorts its output.
  std::vector<const ContactNodeResult*> rows;
  for (const ContactNodeResult& c : inc.contact) rows.push_back(&c);
  std::sort(rows.begin(), rows.end(), [&](const ContactNodeResult* a, const ContactNodeResult* b) {
    return model.node_ids[a->node] < model.node_ids[b->node];
  });
  for (const std::string& var : request.vars) {
    if (var == "CSTR") {
      header(out, "contact stress (slave node,press,tang1,tang2) for all contact elements",
             inc.total_time);
      for (const ContactNodeResult* c : rows)
        row(out, model.node_ids[c->node], {c->pressure, c->shear[0], c->shear[1]});
    } else if (var == "CDIS") {
      header(out, "contact displacement (slave node,gap,slip1,slip2) for all contact elements",
             inc.total_time);
      for (const ContactNodeResult* c : rows)
        row(out, model.node_ids[c->node], {c->gap, c->slip[0], c->slip[1]});
    } else if (var == "CSTATUS") {
      header(out,
             "contact status (slave node,status: 0 open 1 stick 2 slip) for all contact "
             "elements",
             inc.total_time);
      for (const ContactNodeResult* c : rows) {
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "%10" PRId64 " %3d\n",
                      static_cast<std::int64_t>(model.node_ids[c->node]),
                      static_cast<int>(c->status));
        out << buffer;
      }
    } else {
      throw InputError(request.where, "*CONTACT PRINT: variable " + var +
                                          " cannot be printed (Styk prints CSTR, CDIS, CSTATUS)");
    }
  }
  for (std::size_t p = 0; p < inc.contact_pairs.size() && p < model.contact_pairs.size(); ++p) {
    const ContactPair& pair = model.contact_pairs[p];
    header(out,
           "total contact force and moment about the origin on slave " + pair.slave + " of pair " +
               pair.slave + "/" + pair.master,
           inc.total_time);
    vector_row(out, "force", inc.contact_pairs[p].force);
    vector_row(out, "moment", inc.contact_pairs[p].moment);
    law_row(out, model, pair);
  }
  // Pressure penetration (Styk-only): per definition the fluid pressure, the penetrated share and
  // the leak flag, then the penetrated slave nodes with the fluid pressure acting on them.
  for (const PenetrationResult& pr : inc.penetrations) {
    if (pr.pair < 0 || pr.pair >= static_cast<int>(model.contact_pairs.size())) continue;
    const ContactPair& pair = model.contact_pairs[pr.pair];
    header(out,
           "pressure penetration (slave node,fluid pressure) of pair " + pair.slave + "/" +
               pair.master,
           inc.total_time);
    char buffer[160];
    std::snprintf(buffer, sizeof buffer,
                  "  fluid pressure %s, %d of %d slave nodes penetrated, %s\n",
                  fortran_e13_6(pr.pressure).c_str(), pr.penetrated, pr.nodes,
                  pr.leaked ? "leaking" : "not leaking");
    out << buffer;
    for (const ContactNodeResult* c : rows)
      if (c->pair == pr.pair && c->fluid_pressure > 0.0)
        row(out, model.node_ids[c->node], {c->fluid_pressure});
  }
  if (inc.contact_equilibrium.valid) {
    const ContactEquilibrium& e = inc.contact_equilibrium;
    header(out, "equilibrium (applied loads + reactions = 0; contact slave + master = 0)",
           inc.total_time);
    vector_row(out, "applied", e.applied);
    vector_row(out, "reactions", e.reactions);
    vector_row(out, "c.slave", e.contact_slave);
    vector_row(out, "c.master", e.contact_master);
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "  relative residual %s\n",
                  fortran_e13_6(e.relative_residual).c_str());
    out << buffer;
  }
}

}  // namespace styk::io
