// The element families the studies run, as data: the atlas runs every family of this table that
// the registry holds (plug-ins loaded), and names the registered solid types the table lacks, so
// a new formulation is never left out silently. A new family is one row here (its polynomial
// order) plus the mesher's conversion to it (docs/accuracy.md, "Adding a family").
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"

namespace styk::studies {

struct ElementFamily {
  std::string name;
  // Degree of the complete polynomial the shape functions contain: the L2 displacement error
  // falls as h^(order + 1), the energy-norm (stress) error as h^order.
  int order = 1;
  std::string meshing;  // how the studies mesh it, for the docs
};

// Every family the studies know, in the charts' order (colours follow it).
const std::vector<ElementFamily>& family_catalogue();
const ElementFamily* find_family(const std::string& name);

// The catalogue's families that `registry` holds; `unavailable` (may be null) receives one line
// per catalogue family the registry lacks and per registered solid type the catalogue lacks.
std::vector<ElementFamily> available_families(const ElementRegistry& registry,
                                              std::vector<std::string>* unavailable);

}  // namespace styk::studies
