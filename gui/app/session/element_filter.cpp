#include "session/element_filter.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "session/input_checks.hpp"

namespace styk::gui {
namespace {

// A positive id from the digits of `text` (the whole of it); refused otherwise.
Id parse_id(const std::string& text, const std::string& item) {
  const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
  if (!digits || text.size() > 18)
    refuse("element ids: \"" + item + "\" is not an id or a range like 1-500");
  const Id id = static_cast<Id>(std::stoll(text));
  if (id < 1) refuse("element ids: ids start at 1, not \"" + item + "\"");
  return id;
}

}  // namespace

bool ElementDisplayFilter::accepts(const Element& element) const {
  if (!types.empty() && std::find(types.begin(), types.end(), element.type) == types.end())
    return false;
  if (ranges.empty()) return true;
  return std::any_of(ranges.begin(), ranges.end(), [&](const IdRange& r) {
    return element.id >= r.first && element.id <= r.last;
  });
}

std::vector<IdRange> parse_id_ranges(const std::string& text) {
  // Items split at commas and blanks; blanks around a dash belong to its range ("1 - 500").
  std::string joined;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ',') {
      joined += ' ';
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      std::size_t next = i;
      while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
      const bool before_dash = next < text.size() && text[next] == '-';
      const bool after_dash = !joined.empty() && joined.back() == '-';
      if (!before_dash && !after_dash) joined += ' ';
      continue;
    }
    joined += c;
  }
  std::vector<IdRange> ranges;
  std::size_t at = 0;
  while (at < joined.size()) {
    if (joined[at] == ' ') {
      ++at;
      continue;
    }
    std::size_t end = joined.find(' ', at);
    if (end == std::string::npos) end = joined.size();
    const std::string item = joined.substr(at, end - at);
    at = end;
    const std::size_t dash = item.find('-');
    IdRange range;
    if (dash == std::string::npos) {
      range.first = range.last = parse_id(item, item);
    } else {
      range.first = parse_id(item.substr(0, dash), item);
      range.last = parse_id(item.substr(dash + 1), item);
      if (range.last < range.first)
        refuse("element ids: the range \"" + item +
               "\" runs backwards; write the smaller id first");
    }
    ranges.push_back(range);
  }
  return ranges;
}

std::string format_id_ranges(const std::vector<IdRange>& ranges) {
  std::string text;
  for (const IdRange& r : ranges) {
    if (!text.empty()) text += ", ";
    text += std::to_string(r.first);
    if (r.last != r.first) text += "-" + std::to_string(r.last);
  }
  return text;
}

std::vector<std::string> element_types_present(const Model& model) {
  std::set<std::string> types;
  for (const Element& e : model.elements) types.insert(e.type);
  return {types.begin(), types.end()};
}

ElementDisplayFilter make_element_filter(const Model& model, const std::string& ranges,
                                         const std::vector<std::string>& types) {
  ElementDisplayFilter filter;
  filter.ranges = parse_id_ranges(ranges);
  const std::vector<std::string> present = element_types_present(model);
  for (const std::string& type : types) {
    const std::string upper = to_upper(type);
    if (!std::binary_search(present.begin(), present.end(), upper))
      refuse("element type " + upper + " is not in the model");
    if (std::find(filter.types.begin(), filter.types.end(), upper) == filter.types.end())
      filter.types.push_back(upper);
  }
  if (filter.active() && filtered_elements(model, filter).empty())
    refuse("no element passes the filter (ids " +
           (filter.ranges.empty() ? std::string("any") : format_id_ranges(filter.ranges)) + ")");
  return filter;
}

std::vector<int> filtered_elements(const Model& model, const ElementDisplayFilter& filter) {
  std::vector<int> passing;
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    if (filter.accepts(model.elements[e])) passing.push_back(static_cast<int>(e));
  return passing;
}

std::vector<render::Layer> filter_layers(const Model& model,
                                         const std::vector<render::Layer>& layers,
                                         const ElementDisplayFilter& filter) {
  std::vector<render::Layer> kept = layers;
  if (!filter.active()) return kept;
  for (render::Layer& layer : kept) {
    std::vector<int> passing;
    for (int e : layer.elements)
      if (filter.accepts(model.elements[e])) passing.push_back(e);
    layer.elements = std::move(passing);
  }
  return kept;
}

}  // namespace styk::gui
