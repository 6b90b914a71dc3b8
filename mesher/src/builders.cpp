#include "styk/mesher/builders.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "builder_catalogue.hpp"

namespace styk::mesher {

BuilderParams::BuilderParams(std::string builder, std::map<std::string, std::string> values,
                             StaticSolve solve)
    : builder_(std::move(builder)), values_(std::move(values)), solve_(std::move(solve)) {}

Results BuilderParams::solve(const Model& model, const std::string& option,
                             const std::string& alternative) const {
  if (!solve_)
    fail(option + " needs a solve, and this program builds decks without solving; use " +
         alternative + " (or `styk mesh`, which solves)");
  return solve_(model);
}

void BuilderParams::fail(const std::string& message) const {
  throw InputError({"styk mesh " + builder_, 0}, message);
}

const std::string& BuilderParams::text(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) fail("parameter --" + name + " is not declared");  // a builder bug
  return it->second;
}

double BuilderParams::number(const std::string& name) const {
  const std::string& s = text(name);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
    fail("--" + name + ": '" + s + "' is not a number");
  return v;
}

double BuilderParams::positive(const std::string& name) const {
  const double v = number(name);
  if (!(v > 0.0)) fail("--" + name + " must be positive, not " + text(name));
  return v;
}

int BuilderParams::count(const std::string& name, int minimum) const {
  const std::string& s = text(name);
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno != 0 || v < minimum || v > 100000000)
    fail("--" + name + ": expected an integer >= " + std::to_string(minimum) + ", not '" + s + "'");
  return static_cast<int>(v);
}

const std::string& BuilderParams::choice(const std::string& name,
                                         const std::vector<std::string>& allowed) const {
  const std::string& s = text(name);
  for (const std::string& a : allowed)
    if (to_upper(a) == to_upper(s)) return a;
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail("--" + name + ": '" + s + "' is not one of " + list);
}

std::vector<BuilderInfo> builder_catalogue() {
  std::vector<BuilderInfo> all;
  detail::add_beam_builders(all);
  detail::add_solid_builders(all);
  detail::add_contact_builders(all);
  detail::add_shrink_fit_builder(all);
  detail::add_conical_fit_builder(all);
  detail::add_spline_joint_builder(all);
  detail::add_p3g_joint_builder(all);
  detail::add_bolted_flange_builder(all);
  detail::add_stacked_elements_builder(all);
  detail::add_electric_plate_builder(all);
  // SPEC order: compare the section numbers field by field ("§3.1.10" after "§3.1.9").
  auto numbers = [](const std::string& section) {
    std::vector<int> out;
    int value = -1;
    for (char c : section) {
      if (c >= '0' && c <= '9') {
        value = (value < 0 ? 0 : value * 10) + (c - '0');
      } else if (value >= 0) {
        out.push_back(value);
        value = -1;
      }
    }
    if (value >= 0) out.push_back(value);
    return out;
  };
  std::stable_sort(all.begin(), all.end(), [&](const BuilderInfo& a, const BuilderInfo& b) {
    return numbers(a.section) < numbers(b.section);
  });
  return all;
}

BuildResult run_builder(const std::string& name, const std::map<std::string, std::string>& args,
                        const ElementRegistry& registry, StaticSolve solve) {
  const std::vector<BuilderInfo> all = builder_catalogue();
  const auto info =
      std::find_if(all.begin(), all.end(), [&](const BuilderInfo& b) { return b.name == name; });
  if (info == all.end()) {
    std::string list;
    for (const BuilderInfo& b : all) list += (list.empty() ? "" : ", ") + b.name;
    throw InputError({"styk mesh", 0}, "unknown builder '" + name + "'; builders: " + list);
  }
  std::map<std::string, std::string> values;
  for (const ParamDecl& p : info->params) values[p.name] = p.default_value;
  for (const auto& [key, value] : args) {
    if (!values.count(key)) {
      std::string list;
      for (const ParamDecl& p : info->params) list += (list.empty() ? "--" : ", --") + p.name;
      throw InputError({"styk mesh " + name, 0},
                       "unknown parameter --" + key + "; parameters: " + list);
    }
    values[key] = value;
  }
  BuildResult result = info->build(BuilderParams(name, values, std::move(solve)), registry);
  result.model.source = name;
  return result;
}

}  // namespace styk::mesher
