#include "case_options.hpp"

#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace styk::render_test {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

void PrintTo(const ImageCase& c, std::ostream* out) {
  *out << c.name << " " << c.scene;
  for (const std::string& o : c.options) *out << " " << o;
}

render::RenderOptions options_for(const ImageCase& c, int width, int height) {
  render::RenderOptions o;
  o.width = width;
  o.height = height;
  std::string ids, types;
  for (const std::string& word : c.options) {
    const std::size_t eq = word.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument(c.name + ": option without '=': " + word);
    const std::string key = word.substr(0, eq), value = word.substr(eq + 1);
    if (key == "mode")
      o.mode = render::parse_display_mode(value);
    else if (key == "field")
      o.field = value;
    else if (key == "averaging")
      o.averaging = render::parse_averaging(value);
    else if (key == "bands")
      o.bands = std::stoi(value);
    else if (key == "smooth")
      o.smooth = value == "1";
    else if (key == "field_faces_only")
      o.field_faces = value == "1" ? render::FieldFaces::Only : render::FieldFaces::Auto;
    else if (key == "all_faces")
      o.field_faces = value == "1" ? render::FieldFaces::All : render::FieldFaces::Auto;
    else if (key == "range") {
      const std::vector<std::string> ends = split(value, ',');
      if (ends.size() != 2) throw std::invalid_argument(c.name + ": range=MIN,MAX");
      o.range = std::array<double, 2>{std::stod(ends[0]), std::stod(ends[1])};
    } else if (key == "samples")
      o.samples = std::stoi(value);
    else if (key == "labels") {
      for (const std::string& item : split(value, ',')) {
        if (item == "nodes")
          o.labels.nodes = true;
        else if (item == "elements")
          o.labels.elements = true;
        else
          throw std::invalid_argument(c.name + ": labels=nodes,elements");
      }
    } else if (key == "ip_values")
      o.ip_values = value == "1";
    else if (key == "unroll")
      o.unroll = value == "1";
    else if (key == "unroll_axis")
      o.unroll = true, o.unroll_axis = render::parse_unroll_axis(value);
    else if (key == "contact_pair")
      o.contact_pair = value;
    else if (key == "deform")
      o.deform = render::parse_deform(value);
    else if (key == "view")
      o.view.name = value;
    else if (key == "azimuth")
      o.view.azimuth = std::stod(value);
    else if (key == "elevation")
      o.view.elevation = std::stod(value);
    else if (key == "zoom")
      o.view.zoom = std::stod(value);
    else if (key == "perspective")
      o.view.perspective = value == "1";
    else if (key == "layers")
      o.layers = split(value, ',');
    else if (key == "hide")
      o.hidden_layers = split(value, ',');
    else if (key == "elements")
      ids = value;
    else if (key == "types")
      types = value;
    else
      throw std::invalid_argument(c.name + ": unknown option " + key);
  }
  o.filter = render::parse_element_filter(ids, types);
  return o;
}

std::vector<ImageCase> read_cases(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<ImageCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream words(line);
    ImageCase c;
    if (!(words >> c.name >> c.scene)) continue;
    for (std::string w; words >> w;) c.options.push_back(w);
    cases.push_back(c);
  }
  return cases;
}

}  // namespace styk::render_test
