// Reading .dat reports (Styk's or CalculiX's) back into numbers, for cross-checks between the two.
#pragma once

#include <istream>
#include <map>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk {

// One line of a .dat block: the node or element id (0 on a "total" line), the integration point
// (0 unless the block lists element integration points) and the numbers that follow.
struct DatRow {
  Id id = 0;
  int integration_point = 0;
  std::vector<double> values;
  bool local = false;  // a trailing " L": the values are in the node's *TRANSFORM system
  // A trailing name: element results printed in the axes of that *ORIENTATION (ccx prints its
  // first 10 characters).
  std::string label;
};

// One block: "<what> for set <set> and time <time>" followed by its rows. A *SECTION PRINT block
// ("statistics for surface set <set> and time <time>") has what = "statistics" and one row per
// line of numbers (its titles are skipped), id 0.
struct DatBlock {
  std::string what;  // e.g. "displacements (vx,vy,vz)", "total force (fx,fy,fz)"
  std::string set;
  double time = 0.0;
  std::vector<DatRow> rows;
};

// Displacements of every node printed at one time (all "displacements" blocks of that time,
// whatever their set, merged).
struct DatDisplacements {
  double time = 0.0;
  std::map<Id, Vec3> u;
};

// Every block of a .dat file, in file order. Lines outside blocks (ccx prints none for the
// requests Styk knows) are ignored. Throws std::runtime_error naming the line for a row that is
// not made of numbers.
std::vector<DatBlock> parse_dat_blocks(std::istream& in);

// The displacement blocks of a .dat file, one entry per distinct time in file order.
std::vector<DatDisplacements> parse_dat_displacements(std::istream& in);

}  // namespace styk
