// The layouts a results file can be written in. Styk writes Checksummed only (write_results_file);
// PreChecksum reproduces the files of Styk before checksums existed (HDF5's default file format,
// no Fletcher-32, no crc32 attributes, no digest, no refusal of non-finite values), so bench/io
// can measure in one process what the checksums cost. Private to styk_io and its bench.
#pragma once

#include <string>

#include "styk/io/results_file.hpp"

namespace styk::io {

enum class ResultsLayout { Checksummed, PreChecksum };

void write_results_file_as(const std::string& path, const Model& model, const Results& results,
                           ResultsLayout layout);

}  // namespace styk::io
