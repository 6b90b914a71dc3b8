#include "cantilever_model.hpp"

#include <cmath>
#include <stdexcept>

namespace styk::testkit {

Cantilever make_cantilever(const CantileverSpec& spec, const ElementRegistry& registry) {
  const TElement* element = registry.find(spec.type);
  if (element == nullptr) throw std::invalid_argument("unknown element type " + spec.type);
  const std::vector<Vec3>& natural = element->natural_nodes();

  Cantilever out;
  Model& model = out.model;
  model.source = "cantilever";
  const SourceLoc here{"cantilever", 0};
  // Lattice of points (2nx+1) x (2ny+1) x (2nz+1); a node is created where an element uses it.
  const long long lx = 2LL * spec.nx + 1, ly = 2LL * spec.ny + 1, lz = 2LL * spec.nz + 1;
  std::vector<int> node_at(static_cast<std::size_t>(lx * ly * lz), -1);
  std::vector<int> element_nodes(natural.size());
  for (int ez = 0; ez < spec.nz; ++ez)
    for (int ey = 0; ey < spec.ny; ++ey)
      for (int ex = 0; ex < spec.nx; ++ex) {
        for (std::size_t k = 0; k < natural.size(); ++k) {
          const long long i = 2LL * ex + 1 + std::lround(natural[k][0]);
          const long long j = 2LL * ey + 1 + std::lround(natural[k][1]);
          const long long m = 2LL * ez + 1 + std::lround(natural[k][2]);
          const long long at = i + lx * (j + ly * m);
          if (node_at[at] < 0) {
            const Vec3 x{spec.length * i / (lx - 1), spec.width * j / (ly - 1),
                         spec.height * m / (lz - 1)};
            node_at[at] = model.add_node(at + 1, x, here);
          }
          element_nodes[k] = node_at[at];
        }
        const Id id = 1 + ex + static_cast<Id>(spec.nx) * (ey + static_cast<Id>(spec.ny) * ez);
        model.add_element(id, element->name(), element_nodes, here);
      }
  const long long centre = (lx - 1) + lx * ((ly - 1) / 2 + ly * ((lz - 1) / 2));
  out.tip_centre_node = node_at[centre];

  Material steel;
  steel.name = "STEEL";
  steel.young = spec.young;
  steel.poisson = spec.poisson;
  model.materials.push_back(steel);
  Section section;
  section.elset = "EALL";
  section.material = "STEEL";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;

  for (int n = 0; n < model.node_count(); ++n)
    if (model.coords[n][0] == 0.0)
      for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, here});

  // Consistent nodal forces of a uniform shear traction on the tip face: F_i = t * integral N_i dA
  // (face S4, xi = +1, of the last element column).
  Step step;
  step.name = "TIP SHEAR";
  step.has_procedure = true;
  const double traction = spec.tip_force / (spec.width * spec.height);
  std::vector<double> force(model.node_count(), 0.0);
  ElementGeometry geometry;
  Eigen::VectorXd area;
  for (int e = 0; e < model.element_count(); ++e) {
    if ((e % spec.nx) != spec.nx - 1) continue;
    const int* nodes = model.element_nodes(e);
    geometry.X.resize(element->node_count(), 3);
    for (int k = 0; k < element->node_count(); ++k)
      for (int d = 0; d < 3; ++d) geometry.X(k, d) = model.coords[nodes[k]][d];
    geometry.id = model.elements[e].id;
    element->nodal_areas(geometry, 3, area);
    for (int k = 0; k < element->node_count(); ++k) force[nodes[k]] += traction * area(k);
  }
  for (int n = 0; n < model.node_count(); ++n)
    if (force[n] != 0.0) step.cloads.push_back({n, 3, force[n], here});
  model.steps.push_back(step);
  return out;
}

}  // namespace styk::testkit
