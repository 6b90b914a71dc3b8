// Joint benchmark (bench/joints/README.md): the figures of the SPEC §4 joint mechanics at the
// builders' default densities, too long for ctest, each with its wall time and a check against
// its reference (the hand value or the published one, with the tolerance stated):
// - model_b: SPEC §4.2 model B as the 90 deg sector with cyclic symmetry, heated, then the
//   sleeve's rim turned by 1.5 deg (rotation control): the torque-rotation curve and the slipping
//   share to full slip and past it; check: the torque at full slip inside the hand band
//   559-614 N m (mu pi d^2 l p / 2, p = 111-122 MPa); `--full` runs the full model too (ratio);
// - flange_15, flange_10: SPEC §4.6 bolted flange, preload 15 / 10 kN, internal pressure to
//   24 MPa in 0.5 MPa increments with pressure penetration: the leak pressure (the first increment
//   whose penetrated zone reaches the gasket's outer edge, and the one before); reported against
//   the published 16 and 12.5-13 MPa, checked: found, and 10 kN leaks at a lower pressure;
// - conical: SPEC §4.3 conical fit for mu = 0, 0.2, 0.4: the pin's largest Mises stress below
//   mid-engagement (published 58, 42, 35 MPa); checked: it falls with mu;
// - spline: SPEC §4.4 spline joint as the 120 deg cyclic sector (target 30 s); `--full` also the
//   full model (ratio, and the same largest flank pressure).
// Prints the tables and one CSV line per run; writes model_b_curve.csv (and _full) in the
// working directory. Exit code 1 when a check fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "hex_model_builder.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"
#include "styk/studies/static_solve.hpp"

namespace {

using namespace styk;

class Log : public ProgressSink {
 public:
  explicit Log(bool echo) : echo_(echo) {}
  void begin(const std::string&) override {}
  void end(const std::string&, double) override {}
  void info(const std::string& line) override {
    if (echo_) std::fprintf(stderr, "%s\n", line.c_str());
    if (line.find(" iteration ") != std::string::npos) ++iterations;
  }
  int iterations = 0;

 private:
  bool echo_;
};

struct Run {
  Model model;
  Results results;
  double seconds = 0;
  int iterations = 0;
};

Run build_and_solve(const std::string& builder, const std::map<std::string, std::string>& args,
                    const ElementRegistry& registry, bool echo) {
  const auto start = std::chrono::steady_clock::now();
  Run run;
  run.model = mesher::run_builder(builder, args, registry, studies::static_solve(registry)).model;
  Log log(echo);
  run.results = run_static_analysis(run.model, registry, SolveOptions{}, &log, nullptr);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.iterations = log.iterations;
  return run;
}

bool check(bool ok, const std::string& what) {
  std::printf("  check: %s: %s\n", what.c_str(), ok ? "ok" : "FAILED");
  return ok;
}

// SPEC §4.2 model B turned by a prescribed angle; sectors = 4 (cyclic sector) or 1 (full).
bool model_b(const ElementRegistry& registry, bool full, bool echo) {
  std::map<std::string, std::string> args = {
      {"model", "B"}, {"load-case", "rotation"}, {"rotation", "1.5"}};
  if (!full) args["sector"] = "yes";
  const int parts = full ? 1 : 4;
  const Run run = build_and_solve("shrink-fit", args, registry, echo);
  const std::string name = full ? "model_b_full" : "model_b";
  std::ofstream csv(name + "_curve.csv");
  csv << "rotation_deg,torque_Nm,closed,slipping\n";
  std::printf("%s: SPEC 4.2 model B%s, mu 0.4, heated, sleeve rim turned by 1.5 deg\n",
              name.c_str(), full ? " (full)" : " (90 deg sector, cyclic symmetry)");
  std::printf("  %-12s %-12s %-8s %s\n", "rotation", "torque", "closed", "slipping");
  double last_torque = 0, onset = 0;
  for (const IncrementResult& inc : run.results.increments) {
    if (inc.step != 2) continue;
    const double rotation = 1.5 * inc.step_time;
    const double torque = -parts * inc.contact_pairs.at(0).moment[2] / 1000.0;
    int closed = 0, slipping = 0;
    for (const ContactNodeResult& c : inc.contact) {
      closed += c.status != ContactStatus::Open;
      slipping += c.status == ContactStatus::Slip;
    }
    if (onset == 0 && closed > 0 && slipping == closed) onset = torque;
    std::printf("  %8.4f deg %9.1f Nm %6d %6d\n", rotation, torque, closed, slipping);
    csv << rotation << ',' << torque << ',' << closed << ',' << slipping << '\n';
    last_torque = torque;
  }
  std::printf(
      "  full slip reached at %.1f N m, torque at 1.5 deg %.1f N m; %.1f s, %d contact "
      "iterations\n",
      onset, last_torque, run.seconds, run.iterations);
  std::printf("CSV,%s,%d,%.2f,%d,%.2f,%.2f\n", name.c_str(), run.model.element_count(), run.seconds,
              run.iterations, onset, last_torque);
  bool ok = check(onset > 0, "full slip reached");
  ok = check(last_torque >= 559 && last_torque <= 614,
             "torque past full slip inside the hand band 559-614 N m") &&
       ok;
  // The figures docs/contact.md quotes (measured 2026-11-25, this mesh), to 0.5 %.
  ok = check(std::abs(onset - 559.0) <= 0.005 * 559.0, "full slip at 559.0 N m") && ok;
  ok = check(std::abs(last_torque - 567.9) <= 0.005 * 567.9, "torque at 1.5 deg 567.9 N m") && ok;
  if (!full)
    ok = check(run.seconds <= 120, "sector torque curve to full slip within 2 minutes") && ok;
  return ok;
}

// SPEC §4.6: the leak pressure with pressure penetration; returns the leak pressure (0: none).
// `ok` turns false when the flange does not hang on the bolt once the gasket face is flooded:
// half bolt = p pi (54^2 - 25^2) / 16 + p pi 25^2 / 16 = 572.56 p, to 1e-3.
double flange(const ElementRegistry& registry, const std::string& preload, bool echo, bool& ok,
              double& seconds) {
  const Run run = build_and_solve("bolted-flange",
                                  {{"preload", preload},
                                   {"penetration", "yes"},
                                   {"pressure", "24"},
                                   {"pressure-increment", "0.5"}},
                                  registry, echo);
  double before = 0, leak = 0;
  std::printf("flange_%s: SPEC 4.6 bolted flange, preload %s kN, pressure penetration\n",
              preload.c_str(), preload.c_str());
  std::printf("  %-10s %-12s %-10s %s\n", "p (MPa)", "bolt (N)", "penetrated", "leak");
  for (const IncrementResult& inc : run.results.increments) {
    if (inc.step != 2 || inc.penetrations.empty()) continue;
    const PenetrationResult& pr = inc.penetrations[0];
    double bolt = 0;
    for (int n : run.model.nsets.at("BOLT_END").nodes) bolt -= inc.RF[n][2];
    std::printf("  %8.2f %12.1f %6d/%d %s\n", pr.pressure, bolt, pr.penetrated, pr.nodes,
                pr.leaked ? "yes" : "no");
    const double per_mpa = 3.14159265358979323846 * 54.0 * 54.0 / 16;
    if (pr.penetrated == pr.nodes && std::abs(bolt - per_mpa * pr.pressure) > 1e-3 * bolt) {
      std::printf("  flooded but not hanging on the bolt: %.1f N against %.1f\n", bolt,
                  per_mpa * pr.pressure);
      ok = false;
    }
    if (pr.leaked && leak == 0) leak = pr.pressure;
    if (!pr.leaked) before = pr.pressure;
  }
  std::printf("  leak between %.2f and %.2f MPa; %.1f s, %d contact iterations\n", before, leak,
              run.seconds, run.iterations);
  seconds += run.seconds;
  std::printf("CSV,flange_%s,%d,%.2f,%d,%.2f,%.2f\n", preload.c_str(), run.model.element_count(),
              run.seconds, run.iterations, before, leak);
  return leak;
}

double mises(const Tensor6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

bool conical(const ElementRegistry& registry, bool echo) {
  std::printf(
      "conical: SPEC 4.3 conical fit, 20 MPa on the pin top (published max Mises 58, 42, "
      "35 MPa for mu 0, 0.2, 0.4, low in the pin)\n");
  std::vector<double> lower;
  for (const std::string mu : {"0", "0.2", "0.4"}) {
    const Run run = build_and_solve("conical-fit", {{"mu", mu}}, registry, echo);
    const IncrementResult& inc = run.results.increments.back();
    double low = 0, all = 0, z_at = 0;
    for (int e : run.model.elsets.at("PIN").elements) {
      const int* nodes = run.model.element_nodes(e);
      double z = 0;
      for (int k = 0; k < run.model.elements[e].node_count; ++k) z += run.model.coords[nodes[k]][2];
      z /= run.model.elements[e].node_count;
      for (int i = inc.ip_offset[e]; i < inc.ip_offset[e + 1]; ++i) {
        const double m = mises(inc.S[i]);
        if (m > all) {
          all = m;
          z_at = z;
        }
        if (z <= 15) low = std::max(low, m);
      }
    }
    std::printf(
        "  mu %-4s max Mises %.1f MPa in the pin below z = 15, %.1f in the whole pin "
        "(element centre z = %.1f); %.1f s, %d contact iterations\n",
        mu.c_str(), low, all, z_at, run.seconds, run.iterations);
    std::printf("CSV,conical_mu%s,%d,%.2f,%d,%.2f,%.2f\n", mu.c_str(), run.model.element_count(),
                run.seconds, run.iterations, low, all);
    lower.push_back(low);
  }
  return check(lower[0] > lower[1] && lower[1] > lower[2], "the pin's Mises falls with mu");
}

// SPEC §4.4 spline joint under 1000 N m: the 120 deg sector with cyclic symmetry (`--sector
// yes`), and with `--full` the full model beside it for the ratio. Checks: the sector's flanks
// carry 1000 N m (3 x the sector's contact moment, 1e-6) and it solves within the 30 s target;
// with --full the largest flank pressure of the two agrees within 1e-6 relative (the same mesh
// density: the sector equals the full model, docs/contact.md "Cyclic symmetry").
bool spline(const ElementRegistry& registry, bool full, bool echo) {
  std::printf("spline: SPEC 4.4 spline joint, 1000 N m, frictionless\n");
  const auto largest_pressure = [](const IncrementResult& inc) {
    double p = 0;
    for (const ContactNodeResult& c : inc.contact) p = std::max(p, c.pressure);
    return p;
  };
  const Run sector = build_and_solve("spline-joint", {{"sector", "yes"}}, registry, echo);
  const IncrementResult& s = sector.results.increments.back();
  const double moment = -3 * s.contact_pairs.at(0).moment[2] / 1000.0;
  std::printf(
      "  sector: %d elements, %.1f s, %d contact iterations, torque %.3f N m, largest "
      "flank pressure %.2f MPa\n",
      sector.model.element_count(), sector.seconds, sector.iterations, moment, largest_pressure(s));
  std::printf("CSV,spline_sector,%d,%.2f,%d,%.2f,%.2f\n", sector.model.element_count(),
              sector.seconds, sector.iterations, moment, largest_pressure(s));
  bool ok = check(std::abs(moment - 1000.0) < 1e-6 * 1000.0, "sector carries 1000 N m");
  ok = check(sector.seconds <= 30.0, "sector spline joint within 30 s") && ok;
  if (!full) return ok;
  const Run whole = build_and_solve("spline-joint", {}, registry, echo);
  const IncrementResult& w = whole.results.increments.back();
  std::printf(
      "  full: %d elements, %.1f s, %d contact iterations, largest flank pressure %.2f "
      "MPa; sector / full time %.3f\n",
      whole.model.element_count(), whole.seconds, whole.iterations, largest_pressure(w),
      sector.seconds / whole.seconds);
  std::printf("CSV,spline_full,%d,%.2f,%d,%.2f,%.3f\n", whole.model.element_count(), whole.seconds,
              whole.iterations, largest_pressure(w), sector.seconds / whole.seconds);
  return check(std::abs(largest_pressure(w) - largest_pressure(s)) <= 1e-6 * largest_pressure(w),
               "sector and full model: the same largest flank pressure (1e-6)") &&
         ok;
}

}  // namespace

int main(int argc, char** argv) {
  bool echo = false, full = false;
  std::vector<std::string> only;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--log")
      echo = true;
    else if (arg == "--full")
      full = true;
    else
      only.push_back(arg);
  }
  const auto wants = [&](const std::string& name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  const auto registry = test::registry_with_plugins();
  std::printf("CSV columns: run, elements, wall seconds, contact iterations, figure 1, figure 2\n");
  bool ok = true;
  if (wants("model_b")) ok = model_b(registry->registry, false, echo) && ok;
  if (wants("model_b") && full) ok = model_b(registry->registry, true, echo) && ok;
  double leak15 = 0, leak10 = 0;
  if (wants("flange")) {
    bool hangs = true;
    double seconds = 0;
    leak15 = flange(registry->registry, "15", echo, hangs, seconds);
    leak10 = flange(registry->registry, "10", echo, hangs, seconds);
    std::printf("  leak sweep (both preloads): %.1f s\n", seconds);
    ok = check(seconds <= 300, "bolted-flange leak sweep within 5 minutes") && ok;
    ok = check(hangs, "flooded gasket: the half bolt carries 572.56 p (1e-3)") && ok;
    ok = check(leak15 > 0 && leak10 > 0, "both preloads leak by 24 MPa") && ok;
    ok = check(leak10 < leak15, "10 kN leaks at a lower pressure than 15 kN") && ok;
    // The brackets docs/mesher.md quotes (measured 2026-11-25, this mesh and increment); the
    // increment's pressure is the step fraction times 24 MPa, so compared to round-off.
    ok = check(std::abs(leak15 - 11.5) < 1e-6, "15 kN: first leaking increment at 11.5 MPa") && ok;
    ok = check(std::abs(leak10 - 7.5) < 1e-6, "10 kN: first leaking increment at 7.5 MPa") && ok;
    std::printf("  published: 16 MPa (15 kN; experiment 16.5), 12.5-13 MPa (10 kN)\n");
  }
  if (wants("conical")) ok = conical(registry->registry, echo) && ok;
  if (wants("spline")) ok = spline(registry->registry, full, echo) && ok;
  return ok ? 0 : 1;
}
