// The layouts a results file can be written in. Styk writes Sealed only (write_results_file):
// checksummed, and sealed as a whole (styk/io/results_seal.hpp). ChecksummedUnsealed reproduces
// the files of Styk between checksums and the seal (the integrity tests read them; bench/io
// measures what the seal costs); PreChecksum reproduces the files of Styk before checksums existed
// (HDF5's default file format, no Fletcher-32, no crc32 attributes, no digest, no refusal of
// non-finite values), so bench/io can measure in one process what the checksums cost. Private to
// styk_io and its bench.
#pragma once

#include <string>

#include "styk/io/results_file.hpp"

namespace styk::io {

enum class ResultsLayout { Sealed, ChecksummedUnsealed, PreChecksum };

void write_results_file_as(const std::string& path, const Model& model, const Results& results,
                           ResultsLayout layout);

}  // namespace styk::io
