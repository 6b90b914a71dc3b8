// Solving the SPEC §3.1 element tests: build the model with the mesher builder of the case, solve
// it with the static solver, read the measured quantity.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/studies/verify/benchmark_cases.hpp"

namespace styk::verify {

// The deck of `c` meshed with `family` (C3D8, C3D20, C3D14, C3D21, C3D28). The registry must
// know the family (load the plug-ins for the contact hexahedra). Throws InputError.
Model build_case_model(const BenchmarkCase& c, const std::string& family,
                       const ElementRegistry& registry);

// The measured quantity of `c` from nodal displacements `U` (one per model node), with the
// case's sign applied. For WorstPatchStress use measure_case(…, IncrementResult).
double measure_displacements(const BenchmarkCase& c, const Model& model,
                             const std::vector<Vec3>& U);
// The measured quantity from a solved increment (any measurement kind).
double measure_case(const BenchmarkCase& c, const Model& model, const IncrementResult& result);

// Builds, solves and measures one case for one family.
double run_case(const BenchmarkCase& c, const std::string& family, const ElementRegistry& registry);

// Our value per family, or the reason there is none (e.g. the plug-in is not loaded).
struct FamilyOutcome {
  std::optional<double> value;
  std::string failure;
};
struct CaseOutcome {
  BenchmarkCase bench;
  std::array<FamilyOutcome, kFamilyCount> ours;  // kElementFamilies order
};

// Runs every case for every family. A family the registry lacks, or a solve that throws, is
// recorded as a failure of that cell; the others still run. `progress` (may be empty) receives
// "case family" before each solve.
std::vector<CaseOutcome> run_cases(const std::vector<BenchmarkCase>& cases,
                                   const ElementRegistry& registry,
                                   const std::function<void(const std::string&)>& progress = {});

}  // namespace styk::verify
