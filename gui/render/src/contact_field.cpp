#include "contact_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

// The entry a node shows when it is the slave of several pairs: the most engaged one (the highest
// status, slip > stick > open, then the larger pressure). The VTU export uses the same rule.
std::vector<const ContactNodeResult*> entry_per_node(const Model& model, const IncrementResult& inc,
                                                     int only_pair) {
  std::vector<const ContactNodeResult*> entry(model.coords.size(), nullptr);
  for (const ContactNodeResult& c : inc.contact) {
    if (only_pair >= 0 && c.pair != only_pair) continue;
    if (c.node < 0 || static_cast<std::size_t>(c.node) >= entry.size())
      throw InputError({}, "contact output of step " + std::to_string(inc.step) + " increment " +
                               std::to_string(inc.increment) + " names node index " +
                               std::to_string(c.node) + " of a model with " +
                               std::to_string(model.coords.size()) + " nodes");
    const ContactNodeResult*& held = entry[c.node];
    if (!held || c.status > held->status ||
        (c.status == held->status && c.pressure > held->pressure))
      held = &c;
  }
  return entry;
}

double magnitude(const std::array<double, 2>& v) { return std::hypot(v[0], v[1]); }

// Suffix of a two-component tangential quantity: "" / "mag" -> magnitude, "1" / "2" -> along the
// node's tangent t1 / t2; -1 when unknown.
int tangential_component(const std::string& suffix) {
  if (suffix.empty() || suffix == "mag" || suffix == "magnitude") return 2;
  if (suffix == "1" || suffix == "t1") return 0;
  if (suffix == "2" || suffix == "t2") return 1;
  return -1;
}

// The index of the pair whose slave surface is `name` (case-insensitive), or of pair number `name`
// (1-based, the order of the *CONTACT PAIR lines: a results file keeps no surface names); -1 for an
// empty name.
int find_pair(const Model& model, const IncrementResult& inc, const std::string& name) {
  if (name.empty()) return -1;
  char* end = nullptr;
  const long number = std::strtol(name.c_str(), &end, 10);
  if (*end == '\0' && number >= 1) {
    const bool known =
        std::any_of(inc.contact.begin(), inc.contact.end(),
                    [&](const ContactNodeResult& c) { return c.pair == number - 1; });
    if (known) return static_cast<int>(number - 1);
    throw InputError({}, "contact pair " + name + " has no contact output in step " +
                             std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment));
  }
  const std::string wanted = to_upper(name);
  std::string known;
  for (std::size_t p = 0; p < model.contact_pairs.size(); ++p) {
    if (model.contact_pairs[p].slave == wanted) return static_cast<int>(p);
    known += (known.empty() ? "" : ", ") + model.contact_pairs[p].slave;
  }
  throw InputError({}, "no contact pair has the slave surface '" + name + "'; " +
                           (known.empty() ? std::string("the model names no *CONTACT PAIR (a "
                                                        "results file keeps none): give the "
                                                        "pair's number, 1, 2, ...")
                                          : "slave surfaces: " + known));
}

// The faces that carry the output of the pairs that have some (or of `only_pair`): their slave
// surfaces' element faces, 0-based; a node-set slave surface sets `node_surfaces`.
void add_support(const Model& model, const IncrementResult& inc, int only_pair,
                 ScalarField& field) {
  std::vector<char> with_output(model.contact_pairs.size(), 0);
  for (const ContactNodeResult& c : inc.contact)
    if (c.pair >= 0 && static_cast<std::size_t>(c.pair) < with_output.size())
      with_output[c.pair] = 1;
  for (std::size_t p = 0; p < model.contact_pairs.size(); ++p) {
    if (!with_output[p] || (only_pair >= 0 && static_cast<int>(p) != only_pair)) continue;
    const auto it = model.surfaces.find(model.contact_pairs[p].slave);
    if (it == model.surfaces.end()) continue;
    if (it->second.kind == Surface::Kind::Nodes) {
      field.node_surfaces = true;
      continue;
    }
    for (const SurfaceFace& f : it->second.faces) field.support.emplace_back(f.element, f.face - 1);
  }
  std::sort(field.support.begin(), field.support.end());
  field.support.erase(std::unique(field.support.begin(), field.support.end()), field.support.end());
}

}  // namespace

bool is_contact_quantity(const std::string& q) {
  return q == "CPRESS" || q == "CSHEAR" || q == "CSLIP" || q == "CGAP" || q == "CSTATUS";
}

std::vector<std::string> contact_field_names() {
  return {"CPRESS",  "CSHEAR",  "CSHEAR.1", "CSHEAR.2", "CSLIP",
          "CSLIP.1", "CSLIP.2", "CGAP",     "CSTATUS"};
}

ScalarField evaluate_contact_field(const Model& model, const IncrementResult& inc,
                                   const std::string& quantity, const std::string& suffix,
                                   const std::string& drawable, const std::string& pair) {
  const bool tangential = quantity == "CSHEAR" || quantity == "CSLIP";
  const int component = tangential ? tangential_component(suffix) : (suffix.empty() ? 2 : -1);
  if (component < 0) {
    std::string names;
    for (const std::string& n : contact_field_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError(
        {}, "unknown contact field '" + quantity + "." + suffix + "'; contact fields: " + names);
  }
  if (inc.contact.empty())
    throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment) + " holds no contact output (" +
                             (model.contact_pairs.empty() ? "the model has no *CONTACT PAIR"
                                                          : "none was stored") +
                             "), so " + quantity + " cannot be drawn; it holds: " + drawable);

  const int only_pair = find_pair(model, inc, pair);
  ScalarField field;
  field.name = quantity + (tangential && component < 2 ? "." + std::to_string(component + 1) : "");
  field.description = field.name;
  field.location = FieldLocation::Node;
  field.values.assign(model.coords.size(), 0.0);
  field.defined.assign(model.coords.size(), 0);
  field.normals.assign(model.coords.size(), Vec3{});
  if (quantity == "CSTATUS") field.categories = {"open", "stick", "slip"};  // ContactStatus order

  add_support(model, inc, only_pair, field);
  const std::vector<const ContactNodeResult*> entry = entry_per_node(model, inc, only_pair);
  for (std::size_t n = 0; n < entry.size(); ++n) {
    const ContactNodeResult* c = entry[n];
    if (!c) continue;
    field.defined[n] = 1;
    field.normals[n] = c->normal;
    double& v = field.values[n];
    if (quantity == "CPRESS")
      v = c->pressure;
    else if (quantity == "CGAP")
      v = c->gap;
    else if (quantity == "CSTATUS")
      v = static_cast<double>(static_cast<int>(c->status));
    else {
      const std::array<double, 2>& t = quantity == "CSHEAR" ? c->shear : c->slip;
      v = component == 2 ? magnitude(t) : t[component];
    }
  }
  return field;
}

}  // namespace styk::render
