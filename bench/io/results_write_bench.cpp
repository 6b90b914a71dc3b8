// What results-file integrity costs (bench/io/README.md): the arrays `styk solve` writes for the
// 1M-DOF cantilever of bench/README.md (C3D20 200 x 20 x 20: 345 681 nodes, 80 000 elements,
// 27 integration points each, U, RF, S, E and the eight recovered fields), written with the
// checksums Styk writes and in the layout of Styk before checksums, alternately in one process so
// the noisy machine treats both alike; then read back, and checked the way `styk check` does.
//   results_write_bench [NX NY NZ] [--rounds N] [--dir DIR]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "results_file_layout.hpp"
#include "styk/io/results_check.hpp"
#include "styk/io/results_file.hpp"
#include "styk/mesher/cantilever.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Smooth, finite values of the sizes the solver writes for one increment.
styk::Results fill_results(const styk::Model& model) {
  styk::IncrementResult inc;
  const int points_per_element = 27;  // C3D20, full 3 x 3 x 3 rule
  for (const styk::Vec3& x : model.coords) {
    inc.U.push_back({1e-4 * x[0] * x[2], -3e-5 * x[1], 2e-3 * x[0] * x[0]});
    inc.RF.push_back({x[0] == 0.0 ? -0.01 * x[2] : 0.0, 0.0, x[0] == 0.0 ? -1e-3 : 0.0});
    const styk::Tensor6 s{6.0 * x[0] * x[2], 0.1 * x[1], 0.2, 1.5 * x[2], 0.0, 0.01 * x[0]};
    inc.S_nodal_I.push_back(s);
    inc.S_nodal_II.push_back(s);
    inc.E_nodal_I.push_back({s[0] / 2e5, s[1] / 2e5, 0, s[3] / 2e5, 0, 0});
    inc.E_nodal_II.push_back(inc.E_nodal_I.back());
  }
  inc.ip_offset.push_back(0);
  for (int e = 0; e < model.element_count(); ++e) {
    inc.ip_offset.push_back(inc.ip_offset.back() + points_per_element);
    for (int p = 0; p < points_per_element; ++p) {
      inc.S.push_back({1.0 * e + p, 0.5, -0.25, 3.0, 0.0, 1e-3 * p});
      inc.E.push_back({1e-6 * e, 2e-7, 0, 1e-5, 0, 1e-8 * p});
    }
    inc.S_centroid.push_back({1.0 * e, 0.5, -0.25, 3.0, 0.0, 0.0});
    inc.E_centroid.push_back({1e-6 * e, 2e-7, 0, 1e-5, 0, 0.0});
  }
  for (std::size_t k = 0; k < model.connectivity.size(); ++k) {
    inc.S_element_nodes.push_back({1e-3 * k, 0.5, -0.25, 3.0, 0.0, 0.0});
    inc.E_element_nodes.push_back({1e-9 * k, 2e-7, 0, 1e-5, 0, 0.0});
  }
  styk::Results results;
  results.increments.push_back(std::move(inc));
  return results;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  styk::mesher::CantileverSpec spec;
  spec.box.type = "C3D20";
  spec.box.size = {10.0, 1.0, 1.0};
  spec.box.divisions = {200, 20, 20};
  int rounds = 5;
  std::string dir = std::filesystem::temp_directory_path().string();
  int positional = 0;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--rounds" && a + 1 < argc)
      rounds = std::atoi(argv[++a]);
    else if (arg == "--dir" && a + 1 < argc)
      dir = argv[++a];
    else if (positional < 3)
      spec.box.divisions[positional++] = std::atoi(argv[a]);
  }
  const styk::Model model = styk::mesher::make_cantilever(spec);
  const styk::Results results = fill_results(model);
  const std::string plain = dir + "/bench_pre_checksum.styk.h5";
  const std::string checked = dir + "/bench_checksummed.styk.h5";
  std::printf("%d nodes (%d dofs), %d elements, %zu integration points\n", model.node_count(),
              3 * model.node_count(), model.element_count(), results.increments[0].S.size());
  std::vector<double> write_plain, write_checked, read_plain, read_checked, check;
  for (int r = 0; r < rounds; ++r) {
    auto t = Clock::now();
    styk::io::write_results_file_as(plain, model, results, styk::io::ResultsLayout::PreChecksum);
    write_plain.push_back(seconds(t));
    t = Clock::now();
    styk::write_results_file(checked, model, results);
    write_checked.push_back(seconds(t));
    t = Clock::now();
    const auto a = styk::read_results_file(plain);
    read_plain.push_back(seconds(t));
    t = Clock::now();
    const auto b = styk::read_results_file(checked);
    read_checked.push_back(seconds(t));
    t = Clock::now();
    const styk::ResultsCheck report = styk::check_results_file(checked);
    check.push_back(seconds(t));
    std::printf(
        "round %d: write %.3f / %.3f s, read %.3f / %.3f s (before checksums / with), "
        "check %.3f s (%s)\n",
        r + 1, write_plain.back(), write_checked.back(), read_plain.back(), read_checked.back(),
        check.back(), report.verdict == styk::ResultsCheck::Verdict::Whole ? "whole" : "NOT WHOLE");
  }
  std::printf("files: %.1f MB before checksums, %.1f MB with\n",
              std::filesystem::file_size(plain) / 1e6, std::filesystem::file_size(checked) / 1e6);
  std::printf("median write: %.3f s before checksums, %.3f s with (ratio %.2f)\n",
              median(write_plain), median(write_checked),
              median(write_checked) / median(write_plain));
  std::printf("median read:  %.3f s before checksums, %.3f s with (ratio %.2f)\n",
              median(read_plain), median(read_checked), median(read_checked) / median(read_plain));
  std::printf("median styk check: %.3f s\n", median(check));
  std::filesystem::remove(plain);
  std::filesystem::remove(checked);
  return 0;
}
