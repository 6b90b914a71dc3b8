// The element families the studies run, as data: the atlas runs every family of this table that
// the registry holds (plug-ins loaded), and names the registered solid types the table lacks, so
// a new formulation is never left out silently. A new family is one row here (its polynomial
// order) plus the mesher's conversion to it (docs/accuracy.md, "Adding a family").
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"

namespace styk::studies {

// What a family models: the solid problems run the solid families, the beam and plate problems
// (docs/accuracy.md, "Beams and plates") their own.
enum class ElementKind { Solid, Beam, Shell };

struct ElementFamily {
  std::string name;
  // Degree of the complete polynomial the shape functions contain: the L2 displacement error
  // falls as h^(order + 1), the energy-norm (stress) error as h^order.
  int order = 1;
  std::string meshing;  // how the studies mesh it, for the docs
  ElementKind kind = ElementKind::Solid;
  std::string element_type;  // the registry's type; empty: `name`
  std::string integration;   // *BEAM SECTION INTEGRATION= of the family (beams), empty: default

  const std::string& type() const { return element_type.empty() ? name : element_type; }
};

// Every family the studies know, in the charts' order (colours follow it).
const std::vector<ElementFamily>& family_catalogue();
// The catalogue's families of one kind.
std::vector<ElementFamily> families_of_kind(ElementKind kind);
const ElementFamily* find_family(const std::string& name);

// The catalogue's families whose type `registry` holds; `unavailable` (may be null) receives one
// line per catalogue family the registry lacks and per registered type the catalogue lacks.
std::vector<ElementFamily> available_families(const ElementRegistry& registry,
                                              std::vector<std::string>* unavailable);

}  // namespace styk::studies
