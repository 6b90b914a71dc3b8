// Markdown of the SPEC §3.1 element tests: the Tab 3.13 grade table (ours beside the thesis') and
// the value tables (ours, the thesis', theory side by side), and the marked section of
// docs/verification.md they are written into.
#pragma once

#include <string>
#include <vector>

#include "styk/studies/verify/run_benchmark.hpp"

namespace styk::verify {

inline constexpr const char* kTable313Begin = "<!-- BEGIN TABLE 3.13 -->";
inline constexpr const char* kTable313End = "<!-- END TABLE 3.13 -->";

// SPEC §3.1.9 / thesis Tab 3.13: one row per graded case, one column per family, each cell
// "ours / thesis" (A-E per Tab 3.12; "–" not graded by the thesis, "n/a" not computed).
std::string grade_table_markdown(const std::vector<CaseOutcome>& outcomes);

// One table per SPEC section: theory, then per family "ours / thesis (difference)".
std::string value_tables_markdown(const std::vector<CaseOutcome>& outcomes);

// Both, as written between the markers of docs/verification.md.
std::string table_313_section(const std::vector<CaseOutcome>& outcomes);

// `text` with everything between the lines `begin` and `end` replaced by `body` (markers kept).
// Throws std::runtime_error naming the marker that is missing or out of order.
std::string replace_marked_section(const std::string& text, const std::string& begin,
                                   const std::string& end, const std::string& body);

}  // namespace styk::verify
