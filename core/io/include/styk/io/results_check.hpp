// `styk check`: is a results file whole? Verifies the schema version, every checksum (the
// whole-file seal before anything else, Fletcher-32 of each stored chunk, CRC-32 of each dataset,
// the file digest), that every value is a finite
// number, and the internal consistency of counts, ids and the step/increment structure. Every
// dataset of the file is read, known to this build or not.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace styk {

struct ResultsCheck {
  enum class Verdict {
    Whole,         // checksummed, every checksum matches, finite, consistent
    Unverifiable,  // written before checksums; finite and consistent as far as can be seen
    Damaged,       // at least one problem
  };
  Verdict verdict = Verdict::Damaged;
  // One line each, naming the dataset, attribute or group at fault (without the file's path).
  std::vector<std::string> problems;
  // The one-line verdict, without the file's path: "whole — ...", "cannot be verified — ...",
  // "damaged — ...".
  std::string summary;

  int schema_version = 0;
  std::string styk_version;
  std::string digest;             // "crc32:xxxxxxxx" (empty for an older file)
  std::string seal;               // "crc32:xxxxxxxx over N bytes" (empty: not sealed)
  std::size_t datasets = 0;       // datasets read
  std::uint64_t value_bytes = 0;  // bytes of values in them
  int steps = 0;
  int increments = 0;
};

// Never throws for a bad file: whatever is wrong is a problem of the report.
ResultsCheck check_results_file(const std::string& path);

}  // namespace styk
