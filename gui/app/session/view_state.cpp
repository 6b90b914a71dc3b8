#include "session/view_state.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

#include "styk/core/diagnostics.hpp"

namespace styk::gui {
namespace {

constexpr const char* kTag = "**STYK";

std::string trimmed(const std::string& text) {
  const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  const auto first = std::find_if_not(text.begin(), text.end(), blank);
  const auto last = std::find_if_not(text.rbegin(), text.rend(), blank).base();
  return first < last ? std::string(first, last) : std::string{};
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string hex_color(const render::Rgb& color) {
  const auto byte = [](float v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  char text[8];
  std::snprintf(text, sizeof text, "%02X%02X%02X", byte(color.r), byte(color.g), byte(color.b));
  return text;
}

// Throws std::invalid_argument with the reason for anything but six hex digits.
render::Rgb parse_color(const std::string& text) {
  const bool hex = text.size() == 6 && std::all_of(text.begin(), text.end(), [](char c) {
                     return std::isxdigit(static_cast<unsigned char>(c)) != 0;
                   });
  if (!hex) throw std::invalid_argument("COLOR=" + text + " is not six hex digits like CC3311");
  const auto channel = [&](int i) {
    return static_cast<float>(std::stoi(text.substr(2 * i, 2), nullptr, 16)) / 255.0f;
  };
  return {channel(0), channel(1), channel(2)};
}

bool parse_yes_no(const std::string& key, const std::string& value) {
  if (value == "YES") return true;
  if (value == "NO") return false;
  throw std::invalid_argument(key + "=" + value + " is neither YES nor NO");
}

// "KIND, KEY=VALUE, ..." after the tag: the upper-case kind and the upper-case keys with their
// trimmed values (upper-case too: names, types and hex digits all are).
std::pair<std::string, std::map<std::string, std::string>> split_card(const std::string& text) {
  std::pair<std::string, std::map<std::string, std::string>> card;
  std::stringstream items(text);
  std::string item;
  bool first = true;
  while (std::getline(items, item, ',')) {
    item = upper(trimmed(item));
    if (first) {
      card.first = item;
      first = false;
      continue;
    }
    if (item.empty()) continue;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("\"" + item + "\" is not KEY=VALUE");
    const std::string key = trimmed(item.substr(0, eq));
    if (card.second.count(key)) throw std::invalid_argument(key + " is given twice");
    card.second[key] = trimmed(item.substr(eq + 1));
  }
  return card;
}

std::string take(std::map<std::string, std::string>& values, const std::string& key) {
  const auto it = values.find(key);
  if (it == values.end()) return {};
  std::string value = it->second;
  values.erase(it);
  return value;
}

LayerStyle parse_layer(std::map<std::string, std::string> values) {
  LayerStyle style;
  style.name = take(values, "NAME");
  if (style.name.empty()) throw std::invalid_argument("LAYER needs NAME=");
  if (values.count("USER")) style.user = parse_yes_no("USER", take(values, "USER"));
  if (values.count("VISIBLE")) style.visible = parse_yes_no("VISIBLE", take(values, "VISIBLE"));
  const std::string color = take(values, "COLOR");
  if (color.empty()) throw std::invalid_argument("LAYER needs COLOR=");
  style.color = parse_color(color);
  if (!values.empty()) throw std::invalid_argument("LAYER takes no " + values.begin()->first);
  return style;
}

void parse_filter(std::map<std::string, std::string> values, ViewState& state) {
  state.filter_ids = take(values, "IDS");
  std::stringstream types(take(values, "TYPES"));
  for (std::string type; types >> type;) state.filter_types.push_back(type);
  if (!values.empty()) throw std::invalid_argument("FILTER takes no " + values.begin()->first);
  if (state.filter_ids.empty() && state.filter_types.empty())
    throw std::invalid_argument("FILTER needs IDS= or TYPES=");
}

std::string located(const std::string& path, int line, const std::string& message) {
  return path + ":" + std::to_string(line) + ": " + message;
}

}  // namespace

ViewState view_state_of(const LayerTable& layers, const ElementDisplayFilter& filter) {
  ViewState state;
  const std::vector<std::string>& user = layers.user_layers();
  for (const render::Layer& layer : layers.layers()) {
    LayerStyle style;
    style.name = layer.name;
    style.user = std::find(user.begin(), user.end(), layer.name) != user.end();
    style.visible = layer.visible;
    style.color = layer.color;
    state.layers.push_back(style);
  }
  // "1-500, 700" -> "1-500 700": a comma would end the value on the comment line.
  for (const char c : format_id_ranges(filter.ranges))
    if (c != ',') state.filter_ids += c;
  state.filter_types = filter.types;
  return state;
}

void write_view_state(const ViewState& state, std::ostream& out) {
  const bool filter = !state.filter_ids.empty() || !state.filter_types.empty();
  if (state.layers.empty() && !filter) return;
  out << "** styk-gui view: layers and element filter (comment lines for other programs)\n";
  for (const LayerStyle& layer : state.layers)
    out << kTag << " LAYER, NAME=" << layer.name << ", USER=" << (layer.user ? "YES" : "NO")
        << ", VISIBLE=" << (layer.visible ? "YES" : "NO") << ", COLOR=" << hex_color(layer.color)
        << "\n";
  if (filter) {
    out << kTag << " FILTER";
    if (!state.filter_ids.empty()) out << ", IDS=" << state.filter_ids;
    if (!state.filter_types.empty()) {
      out << ", TYPES=";
      for (std::size_t i = 0; i < state.filter_types.size(); ++i)
        out << (i ? " " : "") << state.filter_types[i];
    }
    out << "\n";
  }
}

ReadViewState read_view_state(const std::string& path) {
  ReadViewState read;
  std::ifstream in(path);
  std::string line;
  const std::string tag = kTag;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() < tag.size() || upper(line.substr(0, tag.size())) != tag) continue;
    try {
      auto [kind, values] = split_card(line.substr(tag.size()));
      if (kind == "LAYER") {
        LayerStyle style = parse_layer(std::move(values));
        style.line = number;
        read.state.layers.push_back(std::move(style));
      } else if (kind == "FILTER") {
        ViewState filter;
        parse_filter(std::move(values), filter);
        read.state.filter_ids = filter.filter_ids;
        read.state.filter_types = filter.filter_types;
        read.state.filter_line = number;
      } else {
        throw std::invalid_argument("unknown view line \"" + kind + "\" (LAYER or FILTER)");
      }
    } catch (const std::invalid_argument& e) {
      read.warnings.push_back(located(path, number, std::string(e.what()) + "; line ignored"));
    }
  }
  return read;
}

ElementDisplayFilter apply_view_state(const ViewState& state, const std::string& path,
                                      const Model& model, LayerTable& layers,
                                      std::vector<std::string>& warnings) {
  for (const LayerStyle& style : state.layers) {
    if (!style.user) continue;
    if (model.find_elset(style.name)) {
      layers.add_user_layer(style.name);
    } else {
      warnings.push_back(
          located(path, style.line, "user layer " + style.name + " has no element set; dropped"));
    }
  }
  layers.rebuild(model);
  for (const LayerStyle& style : state.layers) {
    try {
      layers.set_visible(style.name, style.visible);
      layers.set_color(style.name, style.color);
    } catch (const std::out_of_range&) {
      if (!style.user || model.find_elset(style.name))
        warnings.push_back(located(path, style.line,
                                   "the model has no layer " + style.name + "; its style dropped"));
    }
  }
  if (state.filter_ids.empty() && state.filter_types.empty()) return {};
  try {
    return make_element_filter(model, state.filter_ids, state.filter_types);
  } catch (const InputError& e) {
    warnings.push_back(located(path, state.filter_line, "filter dropped: " + e.message()));
    return {};
  }
}

}  // namespace styk::gui
