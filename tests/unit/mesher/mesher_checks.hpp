// Checks shared by the mesher tests: a registry with the built-in elements and the C3D14/C3D21/
// C3D28 plug-ins, and the mesh properties every builder must have.
#pragma once

#include <memory>
#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

// Built-in elements + the contact hexahedra of the build tree's plug-in directory (not the
// template plug-in: the builders' type lists stay those of a plain build). Throws when a
// plug-in is missing.
struct Elements : FullRegistry {
  Elements() : FullRegistry({build_plugin_directory()}) { require({"C3D14", "C3D21", "C3D28"}); }
};

// Sum of det J x weight over every element (full rule); every det J must be positive
// (TElement::jacobian throws naming the element otherwise).
double volume(const Model& model, const ElementRegistry& registry);

// Empty string when conforming, else the first problem: every face (TElement::faces()) is used
// by at most two elements, and two faces with the same corners have identical node sets.
std::string conformity_problem(const Model& model, const ElementRegistry& registry);

// Nodes no element uses.
int free_nodes(const Model& model);

// Per element type, the number of elements.
std::string type_counts(const Model& model);

}  // namespace styk::test
