// Layouts, the machine description and atomic file writing of the studies' reports.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "report_support.hpp"
#include "styk/charts/render_png.hpp"
#include "styk/studies/results/convergence.hpp"
#include "styk/studies/study/families.hpp"
#include "styk/studies/study/report.hpp"

namespace styk::studies {
namespace {

// The value of the first line of `path` starting with `key` (after the separator), or "".
std::string first_value(const std::string& path, const std::string& key, char separator) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) {
      const std::size_t at = line.find(separator);
      if (at == std::string::npos) return "";
      std::string v = line.substr(at + 1);
      while (!v.empty() && (v.front() == ' ' || v.front() == '\t' || v.front() == '"'))
        v.erase(0, 1);
      while (!v.empty() && (v.back() == ' ' || v.back() == '"')) v.pop_back();
      return v;
    }
  return "";
}

}  // namespace

ReportLayout docs_layout(const std::string& docs_dir, const std::string& study) {
  const std::filesystem::path d(docs_dir);
  return {(d / (study + ".md")).string(), (d / "atlas" / (study + ".csv")).string(),
          (d / "images" / "atlas").string(), "images/atlas", "atlas/" + study + ".csv"};
}

ReportLayout output_layout(const std::string& dir, const std::string& study) {
  const std::filesystem::path d(dir);
  return {(d / (study + ".md")).string(), (d / (study + ".csv")).string(), d.string(), ".",
          study + ".csv"};
}

std::string chart_file(const std::string& study, const std::string& problem) {
  return study + "-" + problem + ".png";
}

std::string machine_description() {
  const std::string cpu = first_value("/proc/cpuinfo", "model name", ':');
  const std::string memory_kb = first_value("/proc/meminfo", "MemTotal", ':');
  const std::string os = first_value("/etc/os-release", "PRETTY_NAME", '=');
  std::ostringstream out;
  out << (cpu.empty() ? "unknown CPU" : cpu) << ", " << std::thread::hardware_concurrency()
      << " cores";
  if (!memory_kb.empty())
    out << ", " << static_cast<long long>(std::stod(memory_kb) / 1024 / 1024 + 0.5) << " GB";
  if (!os.empty()) out << ", " << os;
  return out.str();
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      std::remove(temporary.c_str());
      throw std::runtime_error(path + ": cannot write");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot write: " + error.message());
  }
}

namespace detail {

std::vector<std::string> family_order(const std::vector<RunRecord>& records) {
  std::vector<std::string> order;
  for (const ElementFamily& f : family_catalogue()) order.push_back(f.name);
  for (const std::string& f : families_of(records))
    if (std::find(order.begin(), order.end(), f) == order.end()) order.push_back(f);
  return order;
}

void write_chart(const charts::Figure& figure, const std::string& path) {
  const std::string temporary = path + ".part.png";
  charts::write_png(figure, temporary);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot write: " + error.message());
  }
}

}  // namespace detail
}  // namespace styk::studies
