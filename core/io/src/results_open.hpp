// Opening a results file for reading, shared by the reader and `styk check`: a missing file, a
// file whose whole-file seal does not match its bytes (verified before HDF5 reads any of them), a
// file that is not HDF5 and an HDF5 file that HDF5 itself refuses (cut short, superblock broken)
// are told apart in the message.
#pragma once

#include <optional>
#include <string>

#include "h5_util.hpp"
#include "styk/io/results_seal.hpp"

namespace styk::io {

// Opens `path` read-only once its seal, when it has one, matches every byte (stored in `*seal`
// when given; std::nullopt for a file written before seals). Throws std::runtime_error with a
// message without the path ("cannot be opened: No such file or directory", "is not an HDF5 file
// ...", "... — the file is damaged").
h5::Handle open_results_for_reading(const std::string& path,
                                    std::optional<ResultsSeal>* seal = nullptr);

}  // namespace styk::io
