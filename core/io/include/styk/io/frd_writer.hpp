// The CalculiX results format (.frd, ASCII): the mesh and nodal result blocks per increment, as
// ccx writes them for *NODE FILE / *EL FILE, so results open in cgx, PrePoMax and ccx2paraview
// (docs/results.md, "The .frd file").
#pragma once

#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

// The .frd blocks Styk writes, with ccx's block names: DISP (U), FORC (RF), STRESS (S, nodal
// averages of the extrapolated integration-point values), TOSTRAIN (E, likewise), NDTEMP (NT)
// and FLUX (HFL, nodal averages).
enum class FrdField { Displacement, Force, Stress, Strain, Temperature, HeatFlux };

struct FrdFieldOutput {
  FrdField field = FrdField::Displacement;
  bool all_nodes = true;
  std::vector<int> nodes;  // node indices, sorted, when !all_nodes (a request's set)
};

// One output increment of the file and the blocks it holds, in order.
struct FrdIncrement {
  const IncrementResult* increment = nullptr;
  std::vector<FrdFieldOutput> fields;
};

// What write_frd() was asked for and could not write (a variable the .frd does not carry, a
// field an increment holds no values of), one line each, for the caller to warn with.
struct FrdPlan {
  std::vector<FrdIncrement> increments;
  std::vector<std::string> notes;
};

// The blocks the deck's *NODE FILE and *EL FILE requests ask for, by CalculiX's rules: the
// requests in effect in each step (styk/core/output_requests.hpp), the increments FREQUENCY=
// selects, NSET= / ELSET= limiting the nodes written. Empty when no step asks for file output.
FrdPlan frd_plan_from_requests(const Model& model, const Results& results);

// Every field the results hold, at every node, for every increment (step and increment 0: all),
// or for one step (increment 0: every increment of it) or one increment (`styk export --frd`).
FrdPlan frd_plan_everything(const Results& results, int step, int increment);

// Writes the header, the nodes, the elements (each as the .frd element of its formulation:
// see docs/results.md) and the planned blocks to `path` through io::TempFile (nothing is left
// behind on failure). `job` names the file's first line. Throws InputError at the element's line
// for an element no .frd element represents, std::runtime_error when the file cannot be written.
void write_frd(const std::string& path, const Model& model, const ElementRegistry& registry,
               const FrdPlan& plan, const std::string& job);

}  // namespace styk
