// `styk check RESULTS.styk.h5`: every problem found on stderr ("file: problem"), then one verdict
// line on stdout; exit 0 only when the file is whole.
#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "styk/io/results_check.hpp"

namespace styk::cli {

int check_command(const CheckArgs& args) {
  const ResultsCheck report = check_results_file(args.results);
  for (const std::string& problem : report.problems)
    std::cerr << args.results << ": " << problem << "\n";
  std::cout << args.results << ": " << report.summary << "\n";
  switch (report.verdict) {
    case ResultsCheck::Verdict::Whole:
      return kOk;
    case ResultsCheck::Verdict::Unverifiable:
      return kUnverifiable;
    case ResultsCheck::Verdict::Damaged:
      break;
  }
  return kBadInput;
}

}  // namespace styk::cli
