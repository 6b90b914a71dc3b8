// What the penalty-law CLI tests share (penalty_cli_test.cpp, exponential_cli_test.cpp): solving a
// deck of tests/inputs/contact/ with `styk solve`, reading a block of its .dat report, and
// comparing the contact blocks with CalculiX's .dat.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"

namespace styk::testing {

inline const std::string kDecks = std::string(STYK_SOURCE_DIR) + "/tests/inputs/contact/";

// Rows of the .dat block whose header starts with " `what`" (node id -> values), last time only.
inline std::map<long, std::vector<double>> dat_block(const std::string& dat,
                                                     const std::string& what) {
  std::map<long, std::vector<double>> rows;
  std::istringstream in(dat);
  std::string line;
  bool inside = false, header_seen = false;
  while (std::getline(in, line)) {
    if (line.rfind(" " + what, 0) == 0) {
      rows.clear();
      inside = true;
      header_seen = false;
      continue;
    }
    if (!inside) continue;
    if (line.empty()) {
      if (header_seen) inside = false;
      header_seen = true;
      continue;
    }
    std::istringstream fields(line);
    long id = 0;
    fields >> id;
    std::vector<double> values;
    for (double v; fields >> v;) values.push_back(v);
    rows[id] = values;
  }
  return rows;
}

struct Solved {
  CommandResult run;
  std::string dat;
};

// `styk solve` of tests/inputs/contact/`deck`.inp in a fresh scratch directory.
inline Solved solve(const std::string& deck, const std::string& scratch) {
  const std::string dir = scratch_dir(scratch);
  Solved out;
  out.run = run_command(styk_executable() + " solve '" + kDecks + deck + ".inp' -o out", dir);
  out.dat = read_file(dir + "/out/" + deck + ".dat");
  return out;
}

// CalculiX's contact pressures, overclosures and the displacements against Styk's: the same nodes,
// every value within `tolerance` of the largest of its block (the figures are printed).
inline void expect_same_contact_blocks(const std::string& ccx, const std::string& styk,
                                       double tolerance) {
  const std::pair<const char*, const char*> blocks[] = {
      {"contact stress", "contact stress"},
      {"relative contact displacement", "contact displacement"},
      {"displacements", "displacements"}};
  for (const auto& [theirs, ours] : blocks) {
    const auto a = dat_block(ccx, theirs);
    const auto b = dat_block(styk, ours);
    ASSERT_EQ(a.size(), b.size()) << theirs;
    ASSERT_FALSE(a.empty()) << theirs;
    double largest = 0.0, difference = 0.0;
    for (const auto& [id, v] : a) {
      ASSERT_EQ(b.count(id), 1u) << theirs << " node " << id;
      for (std::size_t k = 0; k < v.size(); ++k) {
        largest = std::max(largest, std::abs(v[k]));
        difference = std::max(difference, std::abs(v[k] - b.at(id)[k]));
      }
    }
    std::printf("%s: largest %.6e, difference %.3e (relative %.3e)\n", theirs, largest, difference,
                difference / largest);
    EXPECT_LE(difference, tolerance * largest) << theirs;
  }
}

}  // namespace styk::testing
