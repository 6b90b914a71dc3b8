// `styk render`: draws a results file (or a deck's mesh) headless through OSMesa into PNG.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "registry_setup.hpp"
#include "render_args.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/inp/reader.hpp"
#include "styk/io/results_file.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"

namespace styk::cli {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string strip_extension(const std::string& path) {
  for (const char* ext :
       {".styk.h5", ".inp", ".INP", ".png", ".bmp", ".PNG", ".BMP", ".gif", ".mp4"})
    if (ends_with(path, ext)) return path.substr(0, path.size() - std::string(ext).size());
  return path;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

void parse_size(const std::string& text, int& width, int& height) {
  char x = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 ||
      (x != 'x' && x != 'X'))
    throw InputError({}, "bad picture size '" + text + "'; write WIDTHxHEIGHT, e.g. 1600x1200");
}

const IncrementResult& pick_increment(const Results& results, int step, int increment,
                                      const std::string& path) {
  if (results.increments.empty())
    throw InputError({path, 0}, "the results file holds no increments");
  const int want_step = step > 0 ? step : results.increments.back().step;
  const IncrementResult* found = nullptr;
  std::string available;
  for (const IncrementResult& inc : results.increments) {
    available += fmt::format(" {}/{}", inc.step, inc.increment);
    if (inc.step == want_step && (increment == 0 || inc.increment == increment)) found = &inc;
  }
  if (!found)
    throw InputError(
        {path, 0},
        fmt::format("no step {} increment {} in the results; "
                    "step/increment available:{}",
                    want_step, increment == 0 ? std::string("(last)") : std::to_string(increment),
                    available));
  return *found;
}

std::array<double, 2> parse_range(const std::string& text) {
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == ',') c = ' ';
  std::istringstream in(cleaned);
  std::array<double, 2> range{};
  std::string extra;
  if (!(in >> range[0] >> range[1]) || (in >> extra))
    throw InputError({}, "bad colour range '" + text + "'; write MIN,MAX, e.g. 0,250");
  return range;
}

render::LabelRequest parse_labels(const std::string& text) {
  render::LabelRequest labels;
  for (std::string item : split_list(text)) {
    for (char& c : item) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (item == "nodes" || item == "node")
      labels.nodes = true;
    else if (item == "elements" || item == "element")
      labels.elements = true;
    else
      throw InputError({}, "unknown labels '" + item + "'; use nodes, elements or nodes,elements");
  }
  return labels;
}

render::RenderOptions make_options(const RenderArgs& args, bool has_results) {
  render::RenderOptions o;
  parse_size(args.size, o.width, o.height);
  o.mode = render::parse_display_mode(args.mode);
  o.field = args.field;
  o.averaging = render::parse_averaging(args.averaging);
  o.shell_fibre = render::parse_shell_fibre(args.fibre);
  o.bands = args.bands;
  o.smooth = args.smooth;
  if (args.contact_only && args.all_faces)
    throw InputError({}, "--contact-only and --all-faces exclude each other");
  o.field_faces = args.contact_only ? render::FieldFaces::Only
                  : args.all_faces  ? render::FieldFaces::All
                                    : render::FieldFaces::Auto;
  o.contact_pair = args.contact_pair;
  if (!args.range.empty()) o.range = parse_range(args.range);
  o.ip_values = args.ip_values;
  o.labels = parse_labels(args.labels);
  o.unroll = args.unroll || !args.unroll_axis.empty();
  if (!args.unroll_axis.empty()) o.unroll_axis = render::parse_unroll_axis(args.unroll_axis);
  o.samples = args.samples;
  o.deform =
      render::parse_deform(args.deform.empty() ? (has_results ? "auto" : "none") : args.deform);
  o.undeformed_outline = !args.no_outline;
  o.view.name = args.view;
  o.view.azimuth = args.azimuth;
  o.view.elevation = args.elevation;
  o.view.zoom = args.zoom;
  o.view.perspective = args.perspective;
  o.layers = split_list(args.layers);
  o.hidden_layers = split_list(args.hide_layers);
  o.filter = render::parse_element_filter(args.elements, args.types);
  o.revolve_degrees = args.revolve;
  o.revolve_segments = args.revolve_segments;
  return o;
}

// Runs a program found on PATH with arguments (no shell); returns its exit status, -1 if absent.
int run_program(const std::vector<std::string>& argv) {
  std::vector<char*> raw;
  for (const std::string& a : argv) raw.push_back(const_cast<char*>(a.c_str()));
  raw.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, raw[0], nullptr, nullptr, raw.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

int render_job(const RenderArgs& args, const render::RenderJob& job, const std::string& output) {
  const render::RenderOptions& o = job.options();
  render::OsmesaRenderer renderer(o.width, o.height);
  if (args.animate <= 0) {
    render::write_picture(output, renderer.render(job.frame(1.0)));
    std::cout << "wrote " << output << "\n";
    return 0;
  }
  const bool video = ends_with(output, ".gif") || ends_with(output, ".mp4");
  if (video && !on_path("ffmpeg"))
    throw InputError({}, "--animate to " + output +
                             " needs ffmpeg, which is not on PATH; "
                             "write a PNG sequence with -o NAME.png instead");
  const std::string stem = strip_extension(output);
  const std::string picture_extension =
      render::picture_format(output).empty() ? "png" : render::picture_format(output);
  std::vector<std::string> frames;
  for (int i = 0; i < args.animate; ++i) {
    const double fraction = args.animate == 1 ? 1.0 : double(i) / (args.animate - 1);
    frames.push_back(fmt::format("{}_{:04d}.{}", stem, i, video ? "png" : picture_extension));
    render::write_picture(frames.back(), renderer.render(job.frame(fraction)));
  }
  if (!video) {
    std::cout << "wrote " << frames.size() << " frames " << frames.front() << " .. "
              << frames.back() << "\n";
    return 0;
  }
  std::vector<std::string> command = {"ffmpeg",     "-y", "-loglevel", "error",
                                      "-framerate", "10", "-i",        stem + "_%04d.png"};
  if (ends_with(output, ".mp4"))
    command.insert(command.end(),
                   {"-pix_fmt", "yuv420p", "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2"});
  command.push_back(output);
  if (run_program(command) != 0) throw std::runtime_error("ffmpeg failed to write " + output);
  for (const std::string& frame : frames) std::filesystem::remove(frame);
  std::cout << "wrote " << output << " (" << frames.size() << " frames)\n";
  return 0;
}

}  // namespace

int render_command(const RenderArgs& args) {
  if (args.animate < 0) throw InputError({}, "--animate needs a number of frames >= 1");
  const std::string output =
      args.output.empty() ? strip_extension(args.input) + ".png" : args.output;
  const bool video = ends_with(output, ".gif") || ends_with(output, ".mp4");
  if (render::picture_format(output).empty() && !(video && args.animate > 0))
    throw InputError({args.input, 0}, "cannot write the picture " + output +
                                          ": write .png or .bmp" +
                                          (args.animate > 0 ? " (or .gif/.mp4 with ffmpeg)" : ""));
  if (args.unroll || !args.unroll_axis.empty()) {
    if (args.animate > 0)
      throw InputError({args.input, 0}, "--animate moves the 3D view; the unrolled map is still");
  }
  PluginLibraries libraries;  // outlives the registry: plug-in code lives in it
  const ElementRegistry registry = make_registry(libraries);
  const bool results_file = ends_with(args.input, ".styk.h5");
  ResultsFileContents contents;
  const IncrementResult* increment = nullptr;
  if (results_file) {
    contents = read_results_file(args.input);  // InputError "file: ..." on any damage
    if (!contents.verified) std::cerr << unverified_notice(args.input) << "\n";
    increment = &pick_increment(contents.results, args.step, args.increment, args.input);
  } else {
    if (args.step > 0 || args.increment > 0)
      throw InputError({args.input, 0},
                       "--step/--inc need a results file (.styk.h5); a deck "
                       "holds only the mesh");
    contents.model = read_inp(args.input, registry);
  }
  try {
    render::RenderOptions options = make_options(args, results_file);
    if (contents.model.source.empty())
      options.model_name = std::filesystem::path(args.input).filename().string();
    const render::RenderJob job(contents.model, registry, increment, std::move(options));
    return render_job(args, job, output);
  } catch (const InputError& e) {
    if (!e.where().file.empty()) throw;
    throw InputError({args.input, 0}, e.message());  // name the input the option applies to
  }
}

}  // namespace styk::cli
