// Gmsh's element types (numbers, names, dimensions, node counts: the MSH format's table) and
// their Styk counterparts with the node order converted from Gmsh's to CalculiX's.
#pragma once

#include <string>
#include <vector>

#include "styk/gmsh/gmsh_import.hpp"

namespace styk::gmsh {

struct GmshType {
  int number = 0;
  const char* name = "";
  int dimension = 0;
  int nodes = 0;
};

// nullptr for a number the table does not hold.
const GmshType* find_gmsh_type(int number);

// What a Gmsh element becomes: a Styk type and, for each of its nodes in CalculiX's order, the
// index of that node in Gmsh's order.
struct StykElementMapping {
  std::string type;
  std::vector<int> gmsh_index;
};

// The Styk element of a Gmsh type of the mesh's highest dimension. Empty `type` when Styk has
// none: `why` then says so by name (with what to do instead where there is something).
StykElementMapping styk_mapping(const GmshType& gmsh, const GmshImportOptions& options,
                                std::string& why);

}  // namespace styk::gmsh
