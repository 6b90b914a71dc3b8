#include "styk/mesher/shell_mesh.hpp"

#include <cmath>
#include <stdexcept>

#include "styk/core/diagnostics.hpp"

namespace styk::mesher {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The node grid of the patch: per direction the graded element boundaries, with the mid-points
// between them for quadratic shells (order 2).
std::vector<double> grid_parameters(int divisions, double grading, int order) {
  const std::vector<double> ends = graded_parameters(divisions, grading);  // 0 .. 1
  std::vector<double> out;
  for (int k = 0; k < divisions; ++k) {
    out.push_back(2.0 * ends[k] - 1.0);
    if (order == 2) out.push_back(ends[k] + ends[k + 1] - 1.0);
  }
  out.push_back(1.0);
  return out;
}

int shell_node_count(const std::string& type, const ElementRegistry& registry) {
  const TElement* f = registry.find(type);
  if (f == nullptr || f->form() != ElementForm::Shell)
    throw InputError({}, "shell mesh: " + type +
                             " is no shell element type (S4, S4R, S8, S8R, S9, "
                             "S9R)");
  const int n = f->node_count();
  if (n != 4 && n != 8 && n != 9)
    throw InputError({}, "shell mesh: " + type + " has " + std::to_string(n) +
                             " nodes; the shell mesher makes 4-, 8- and 9-node quadrilaterals");
  return n;
}

void check_spec(const ShellMeshSpec& spec) {
  if (spec.divisions_u < 1 || spec.divisions_v < 1)
    throw InputError({}, "shell mesh: divisions must be >= 1");
  if (!(spec.grading_u > 0) || !(spec.grading_v > 0))
    throw InputError({}, "shell mesh: gradings must be > 0");
  if (spec.elset.empty()) throw InputError({}, "shell mesh: the element set needs a name");
}

}  // namespace

Mesh mesh_shell_patch(const PatchMap& map, const ShellMeshSpec& spec,
                      const ElementRegistry& registry, bool closed_u) {
  check_spec(spec);
  if (closed_u && spec.divisions_u < 3)
    throw InputError({}, "shell mesh: a closed patch needs at least 3 divisions around it");
  const int nodes_per_element = shell_node_count(spec.type, registry);
  const int order = nodes_per_element == 4 ? 1 : 2;
  const std::vector<double> u = grid_parameters(spec.divisions_u, spec.grading_u, order);
  const std::vector<double> v = grid_parameters(spec.divisions_v, spec.grading_v, order);
  const int gu = static_cast<int>(u.size()), gv = static_cast<int>(v.size());
  const int columns = closed_u ? gu - 1 : gu;  // a closed patch's last column is its first
  Mesh mesh;
  std::vector<int> index(static_cast<std::size_t>(columns) * gv, -1);
  const bool centres = nodes_per_element == 9;
  for (int j = 0; j < gv; ++j)
    for (int i = 0; i < columns; ++i) {
      if (order == 2 && i % 2 == 1 && j % 2 == 1 && !centres) continue;  // 8 nodes: no centre
      index[i + static_cast<std::size_t>(columns) * j] = mesh.add_node(map(u[i], v[j]));
    }
  const auto at = [&](int i, int j) {
    return index[i % columns + static_cast<std::size_t>(columns) * j];
  };
  std::vector<int> elements;
  for (int ej = 0; ej < spec.divisions_v; ++ej)
    for (int ei = 0; ei < spec.divisions_u; ++ei) {
      const int i0 = ei * order, j0 = ej * order, s = order;
      std::vector<int> q = {at(i0, j0), at(i0 + s, j0), at(i0 + s, j0 + s), at(i0, j0 + s)};
      if (order == 2)
        q.insert(q.end(), {at(i0 + 1, j0), at(i0 + 2, j0 + 1), at(i0 + 1, j0 + 2), at(i0, j0 + 1)});
      if (centres) q.push_back(at(i0 + 1, j0 + 1));
      elements.push_back(mesh.add_element(spec.type, std::move(q)));
    }
  mesh.add_to_element_set(spec.elset, elements);
  std::vector<int> all;
  for (int k = 0; k < static_cast<int>(mesh.nodes.size()); ++k) all.push_back(k);
  mesh.add_to_node_set(spec.elset, all);
  const auto side = [&](const std::string& name, bool along_u, int fixed) {
    std::vector<int> nodes;
    for (int k = 0; k < (along_u ? columns : gv); ++k) {
      const int n = along_u ? at(k, fixed) : at(fixed, k);
      if (n >= 0) nodes.push_back(n);
    }
    mesh.add_to_node_set(spec.elset + "_" + name, nodes);
  };
  side("SIDE1", true, 0);
  side("SIDE3", true, gv - 1);
  if (!closed_u) {
    side("SIDE2", false, gu - 1);
    side("SIDE4", false, 0);
  }
  return mesh;
}

Mesh shell_plate(double a, double b, const ShellMeshSpec& spec, const ElementRegistry& registry) {
  if (!(a > 0) || !(b > 0)) throw InputError({}, "shell plate: the sides must be > 0");
  return mesh_shell_patch(
      [a, b](double u, double v) {
        return Vec3{0.5 * a * (u + 1), 0.5 * b * (v + 1), 0.0};
      },
      spec, registry);
}

Mesh shell_cylindrical_panel(double radius, double length, double angle_degrees,
                             const ShellMeshSpec& spec, const ElementRegistry& registry) {
  if (!(radius > 0) || !(length > 0))
    throw InputError({}, "cylindrical panel: the radius and the length must be > 0");
  if (!(angle_degrees > 0) || angle_degrees > 360)
    throw InputError({}, "cylindrical panel: the angle must lie in (0, 360] degrees");
  const double half = 0.5 * angle_degrees * kPi / 180;
  const bool closed = angle_degrees == 360;
  return mesh_shell_patch(
      [=](double u, double v) {
        const double phi = u * half;
        return Vec3{radius * std::sin(phi), 0.5 * length * (v + 1), radius * std::cos(phi)};
      },
      spec, registry, closed);
}

Mesh shell_hemisphere(double radius, double hole_degrees, double sweep_degrees,
                      const ShellMeshSpec& spec, const ElementRegistry& registry) {
  if (!(radius > 0)) throw InputError({}, "hemisphere: the radius must be > 0");
  if (!(hole_degrees > 0) || !(hole_degrees < 90))
    throw InputError({},
                     "hemisphere: the hole must lie in (0, 90) degrees (a quadrilateral mesh "
                     "cannot close at the pole)");
  if (!(sweep_degrees > 0) || sweep_degrees > 360)
    throw InputError({}, "hemisphere: the sweep must lie in (0, 360] degrees");
  const double top = (90 - hole_degrees) * kPi / 180, sweep = sweep_degrees * kPi / 180;
  const bool closed = sweep_degrees == 360;
  return mesh_shell_patch(
      [=](double u, double v) {
        const double psi = 0.5 * (u + 1) * sweep, lambda = 0.5 * (v + 1) * top;
        return Vec3{radius * std::cos(lambda) * std::cos(psi),
                    radius * std::cos(lambda) * std::sin(psi), radius * std::sin(lambda)};
      },
      spec, registry, closed);
}

}  // namespace styk::mesher
