#include "numbers.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace styk::inp {

namespace {

std::string field_label(std::size_t index, const std::string& what) {
  return "field " + std::to_string(index + 1) + " (" + what + ")";
}

std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}

// CalculiX reads numbers with Fortran's list-directed input, where D is an exponent letter like
// E ("1.d0", "2.5D-3"): the text with its one D or d read as e, or empty when it has none.
std::string with_e_exponent(std::string_view text) {
  const std::size_t d = text.find_first_of("dD");
  if (d == std::string_view::npos || d == 0 ||
      text.find_first_of("dD", d + 1) != std::string_view::npos)
    return {};
  std::string e(text);
  e[d] = 'e';
  return e;
}

// Converts text; returns an empty string on success, otherwise what is wrong with it.
std::string to_real(std::string_view text, double& value) {
  if (text.empty()) return "empty, expected a number";
  const std::string_view digits = without_plus(text);
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc() && end != digits.data() + digits.size()) {
    const std::string e = with_e_exponent(digits);
    if (!e.empty()) {
      const auto parsed = std::from_chars(e.data(), e.data() + e.size(), value);
      ec = parsed.ec;
      end = parsed.ptr == e.data() + e.size() ? digits.data() + digits.size() : digits.data();
    }
  }
  if (ec == std::errc::result_out_of_range) return "out of range for a double, read " + quote(text);
  if (ec != std::errc() || end != digits.data() + digits.size())
    return "expected a number, read " + quote(text);
  if (!std::isfinite(value)) return "expected a finite number, read " + quote(text);
  return {};
}

std::string to_integer(std::string_view text, std::int64_t& value) {
  if (text.empty()) return "empty, expected an integer";
  const std::string_view digits = without_plus(text);
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range)
    return "out of range for an integer, read " + quote(text);
  if (ec != std::errc() || end != digits.data() + digits.size())
    return "expected an integer, read " + quote(text);
  return {};
}

const std::string& field_text(const DataLine& line, std::size_t index, const std::string& what) {
  if (index >= line.fields.size())
    throw InputError(line.where, field_label(index, what) + " is missing (the line has " +
                                     std::to_string(line.fields.size()) + " field" +
                                     (line.fields.size() == 1 ? "" : "s") + ")");
  return line.fields[index];
}

}  // namespace

double real_field(const DataLine& line, std::size_t index, const std::string& what) {
  double value = 0.0;
  const std::string why = to_real(field_text(line, index, what), value);
  if (!why.empty()) throw InputError(line.where, field_label(index, what) + ": " + why);
  return value;
}

std::int64_t integer_field(const DataLine& line, std::size_t index, const std::string& what) {
  std::int64_t value = 0;
  const std::string why = to_integer(field_text(line, index, what), value);
  if (!why.empty()) throw InputError(line.where, field_label(index, what) + ": " + why);
  return value;
}

int displacement_dof(const DataLine& line, std::size_t index, const std::string& what) {
  const std::int64_t dof = integer_field(line, index, what);
  if (dof == 11)
    throw InputError(line.where, what +
                                     " 11 (temperature) is not supported yet; Styk reads dofs "
                                     "1..6 (ux, uy, uz, rx, ry, rz)");
  if (dof < 1 || dof > 6)
    throw InputError(line.where, what + " " + std::to_string(dof) +
                                     " is out of range; Styk reads dofs 1..6 (ux, uy, uz, rx, "
                                     "ry, rz)");
  return static_cast<int>(dof);
}

int boundary_dof(const DataLine& line, std::size_t index, const std::string& what) {
  const std::int64_t dof = integer_field(line, index, what);
  if ((dof < 1 || dof > 6) && dof != 9 && dof != 11)
    throw InputError(line.where, what + " " + std::to_string(dof) +
                                     " is out of range; Styk reads dofs 1..6 (ux, uy, uz, rx, "
                                     "ry, rz), 11 (temperature) and 9 (electric potential)");
  return static_cast<int>(dof);
}

Id id_field(const DataLine& line, std::size_t index, const std::string& what) {
  const std::int64_t value = integer_field(line, index, what);
  if (value < 1)
    throw InputError(line.where, field_label(index, what) + ": ids must be positive, read " +
                                     std::to_string(value));
  if (value > kLargestId)
    throw InputError(line.where, field_label(index, what) + ": " + std::to_string(value) +
                                     " is larger than the largest id, " +
                                     std::to_string(kLargestId) +
                                     " (CalculiX's 32-bit ids; the .dat and .frd id columns "
                                     "hold 10 digits)");
  return value;
}

double real_value(const std::string& text, const std::string& what, const SourceLoc& where) {
  double value = 0.0;
  const std::string why = to_real(text, value);
  if (!why.empty()) throw InputError(where, what + ": " + why);
  return value;
}

std::int64_t integer_value(const std::string& text, const std::string& what,
                           const SourceLoc& where) {
  std::int64_t value = 0;
  const std::string why = to_integer(text, value);
  if (!why.empty()) throw InputError(where, what + ": " + why);
  return value;
}

bool looks_like_number(const std::string& text) {
  double value = 0.0;
  const std::string why = to_real(text, value);
  return why.empty() || why.rfind("out of range", 0) == 0 || why.rfind("expected a finite", 0) == 0;
}

bool names_a_set(const std::string& text) { return !text.empty() && !looks_like_number(text); }

bool looks_like_integer(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  if (i == text.size()) return false;
  for (; i < text.size(); ++i)
    if (text[i] < '0' || text[i] > '9') return false;
  return true;
}

}  // namespace styk::inp
