// Axisymmetric test decks written as CalculiX input text (so the same file runs in Styk and in
// ccx): structured CAX4/CAX8/CAX4R/CAX8R meshes of rectangles in the r-z (x-y) plane.
// Header-only.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace styk::test {

// A rectangle r0..r1 x z0..z1 meshed nr x nz (radial sizes graded: last / first = grading),
// numbered from `first_node` / `first_element`; nodes at equal positions are merged across
// rectangles by the caller through shared ids (`node_at`).
class AxiMesh {
 public:
  explicit AxiMesh(std::string type) : type_(std::move(type)) {}

  // Meshes a rectangle into element set `elset`; returns its elements in order (radial fastest).
  // Rectangles of the same `body` share nodes where they meet; different bodies never do (two
  // bodies touching along a line get coincident, separate nodes: a contact interface).
  std::vector<int> rectangle(const std::string& elset, double r0, double r1, int nr, double z0,
                             double z1, int nz, double grading = 1.0, double z_grading = 1.0,
                             int body = 0) {
    body_ = body;
    const bool quadratic = type_.find('8') != std::string::npos;
    const std::vector<double> rs = graded(r0, r1, nr, grading), zs = graded(z0, z1, nz, z_grading);
    std::vector<int> out;
    for (int j = 0; j < nz; ++j)
      for (int i = 0; i < nr; ++i) {
        const double ra = rs[i], rb = rs[i + 1], za = zs[j], zb = zs[j + 1];
        std::vector<int> n = {node_at(ra, za), node_at(rb, za), node_at(rb, zb), node_at(ra, zb)};
        if (quadratic) {
          n.push_back(node_at(0.5 * (ra + rb), za));
          n.push_back(node_at(rb, 0.5 * (za + zb)));
          n.push_back(node_at(0.5 * (ra + rb), zb));
          n.push_back(node_at(ra, 0.5 * (za + zb)));
        }
        elements_.push_back(n);
        elsets_[elset].push_back(static_cast<int>(elements_.size()));
        out.push_back(static_cast<int>(elements_.size()));
      }
    return out;
  }

  int node_at(double r, double z) {
    const auto key = std::make_tuple(body_, std::llround(r * 1e9), std::llround(z * 1e9));
    const auto it = ids_.find(key);
    if (it != ids_.end()) return it->second;
    nodes_.push_back({r, z});
    bodies_.push_back(body_);
    ids_[key] = static_cast<int>(nodes_.size());
    return static_cast<int>(nodes_.size());
  }

  // Node ids whose position satisfies `inside` (of body `body`; -1: any body).
  template <typename F>
  std::vector<int> nodes_where(F inside, int body = -1) const {
    std::vector<int> out;
    for (std::size_t k = 0; k < nodes_.size(); ++k)
      if ((body < 0 || bodies_[k] == body) && inside(nodes_[k][0], nodes_[k][1]))
        out.push_back(static_cast<int>(k + 1));
    return out;
  }

  // Element faces (id, P/S number 1..4) whose two corners satisfy `on`.
  template <typename F>
  std::vector<std::pair<int, int>> faces_where(const std::vector<int>& elements, F on) const {
    std::vector<std::pair<int, int>> out;
    for (int e : elements)
      for (int f = 0; f < 4; ++f) {
        const auto& a = nodes_[elements_[e - 1][f] - 1];
        const auto& b = nodes_[elements_[e - 1][(f + 1) % 4] - 1];
        if (on(a[0], a[1]) && on(b[0], b[1])) out.push_back({e, f + 1});
      }
    return out;
  }

  const std::vector<std::array<double, 2>>& nodes() const { return nodes_; }

  std::string mesh_text() const {
    std::ostringstream out;
    out.precision(17);
    out << "*NODE, NSET=NALL\n";
    for (std::size_t k = 0; k < nodes_.size(); ++k)
      out << k + 1 << ", " << nodes_[k][0] << ", " << nodes_[k][1] << ", 0.\n";
    for (const auto& [name, list] : elsets_) {
      out << "*ELEMENT, TYPE=" << type_ << ", ELSET=" << name << "\n";
      for (int e : list) {
        out << e;
        for (int n : elements_[e - 1]) out << ", " << n;
        out << "\n";
      }
    }
    return out.str();
  }

 private:
  static std::vector<double> graded(double a, double b, int n, double ratio) {
    const double q = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;
    std::vector<double> t(n + 1, 0.0);
    double step = 1.0, total = 0.0;
    for (int i = 0; i < n; ++i) total += step, t[i + 1] = total, step *= q;
    for (double& v : t) v = a + (b - a) * v / total;
    t[n] = b;
    return t;
  }

  std::string type_;
  int body_ = 0;
  std::vector<int> bodies_;
  std::vector<std::array<double, 2>> nodes_;
  std::vector<std::vector<int>> elements_;
  std::map<std::string, std::vector<int>> elsets_;
  std::map<std::tuple<int, long long, long long>, int> ids_;
};

inline std::string id_lines(const std::vector<int>& ids) {
  std::ostringstream out;
  for (std::size_t k = 0; k < ids.size(); ++k)
    out << ids[k] << ((k + 1) % 16 == 0 || k + 1 == ids.size() ? "\n" : ", ");
  return out.str();
}

}  // namespace styk::test
