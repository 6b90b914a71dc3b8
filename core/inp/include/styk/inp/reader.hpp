// Reads an Abaqus/CalculiX keyword deck (.inp) into a validated Model. The language subset is
// documented keyword by keyword in docs/input.md.
#pragma once

#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk {

// Parses the deck at `path` (and the files it *INCLUDEs) and checks that the model is complete:
// nodes, elements, a section for every element, materials with elastic constants, at least one
// step. Element types are looked up in `registry`.
//
// Throws InputError pointing at the offending file (as given, or the included file's path) and
// 1-based line; line 0 means the deck as a whole (e.g. "no *NODE in the deck").
//
// `completeness`: Complete (the default) demands what an analysis needs; Draft accepts a model
// still being built in the desktop program (an autosave, a deck saved half-way) that lacks nodes,
// elements or a step. Everything a draft holds is checked as usual.
enum class DeckCompleteness { Complete, Draft };
Model read_inp(const std::string& path, const ElementRegistry& registry,
               DeckCompleteness completeness = DeckCompleteness::Complete);

}  // namespace styk
