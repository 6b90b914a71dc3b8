// The Styk results file (.styk.h5): the mesh and every converged increment in one HDF5 file.
// The schema is documented in docs/results.md. No HDF5 type appears here, so including this header
// costs nothing beyond the model and results headers.
#pragma once

#include <string>

#include "styk/core/diagnostics.hpp"
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
  // True when the file carries checksums and every one read matched (docs/results.md,
  // "Integrity"). False for a file written before results files carried checksums: it was read,
  // its values are finite and its counts consistent, but whether they are what the solver wrote
  // cannot be verified; readers say so with unverified_notice().
  bool verified = false;
  // True when the file carries the whole-file seal (docs/results.md, "Integrity"), verified
  // before HDF5 read it. Files written before Styk sealed its results files have none.
  bool sealed = false;
};

// The results to write hold a NaN or an infinity (a failed solve: an overflow, a singular
// system): nothing is written. A NotConvergedError, so `styk solve` exits with code 2.
class NonFiniteResultsError : public NotConvergedError {
 public:
  using NotConvergedError::NotConvergedError;
};

// Writes `model`'s mesh and every increment of `results` to `path`, every dataset checksummed
// (Fletcher-32 per stored chunk, CRC-32 per dataset, a digest over them all). The data goes to
// `path + ".tmp"` first and is renamed to `path` only when everything was written, so a failure
// never leaves a partial file behind (nor replaces an existing one). Throws NonFiniteResultsError
// when any value is a NaN or an infinity (naming the dataset and the node, element or point), and
// std::runtime_error with a readable message on any other failure, including results that do not
// match the model's sizes.
void write_results_file(const std::string& path, const Model& model, const Results& results);

// Reads a file written by write_results_file(), verifying every checksum of what it reads and the
// file digest, and refusing NaN and infinities. Throws InputError ("<path>: message", line 0)
// when the file cannot be opened, is not a Styk results file, has a newer schema version, is
// damaged ("dataset /steps/step_2/increment_1/U: checksum mismatch — the file is damaged"), holds
// a value that is not a finite number, or is inconsistent.
ResultsFileContents read_results_file(const std::string& path);

// "<path>: notice: written before Styk results files carried checksums; what it holds cannot be
// verified" — what readers print (CLI, on stderr) or show (GUI) for an unverified file.
std::string unverified_notice(const std::string& path);

}  // namespace styk
