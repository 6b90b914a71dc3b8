// The Styk results file (.styk.h5): the mesh and every converged increment in one HDF5 file.
// The schema is documented in docs/results.md. No HDF5 type appears here, so including this header
// costs nothing beyond the model and results headers.
#pragma once

#include <string>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"

namespace styk {

// What read_results_file() recovers. `model` holds only the mesh part of the original model
// (source, heading, nodes, elements with their types and connectivity, node and element sets);
// materials, sections, loads and steps are not stored in the results file.
struct ResultsFileContents {
  Model model;
  Results results;
  int schema_version = 0;
  std::string styk_version;  // version of the Styk build that wrote the file
};

// Writes `model`'s mesh and every increment of `results` to `path`. The data goes to
// `path + ".tmp"` first and is renamed to `path` only when everything was written, so a failure
// never leaves a partial file behind (nor replaces an existing one). Throws std::runtime_error with
// a readable message on any failure, including results that do not match the model's sizes.
void write_results_file(const std::string& path, const Model& model, const Results& results);

// Reads a file written by write_results_file(). Throws std::runtime_error when the file cannot be
// opened, is not a Styk results file, has a newer schema version, or is inconsistent.
ResultsFileContents read_results_file(const std::string& path);

}  // namespace styk
