// Builder of SPEC §6.1: the electric potential in a plate 14 x 14 x 0.5 with and without a central
// slit 0.02 x 5, -1 V at point A and 0 V at point B, diagonal conductivity. The point positions are
// only in the thesis' lost figure; the stand-in (docs/mesher.md) puts A and B at the midpoints of
// the left and right edges, the slit across the line AB at the centre, and the measuring points
// C, D, E on x = 6 with their partners G, H, I mirrored to x = 8. The plate is symmetric under
// x -> 14 - x with A and B swapped, so phi(G) = -1 - phi(C) on a symmetric mesh: every pair sums to
// -1 and the slit shows as a wider difference within each pair.
//
// Mesh: 3 x 3 blocks (columns x = 0..6.99, 6.99..7.01, 7.01..14; rows y = 0..4.5, 4.5..9.5,
// 9.5..14), one element through the thickness; the slit is the middle block, left out. C3D28:
// the element layers along the two edges holding A and B become 28-node elements (their edge face
// S1), 20-node elsewhere, as the thesis; C3D20 everywhere; CPS4 is the 2D 4-node model (plane
// elements of thickness 0.5).
#include <cmath>
#include <cstdio>

#include "builder_catalogue.hpp"
#include "builder_support.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::mesher::detail {
namespace {

const std::vector<std::string> kPlateFamilies = {"C3D28", "C3D20", "CPS4"};
constexpr double kSide = 14.0, kThickness = 0.5, kSlitWidth = 0.02, kSlitLength = 5.0;

struct PlatePoint {
  const char* name;
  Vec3 target;
};
// Measuring points of the stand-in (z = 0 face); G, H, I mirror C, D, E through x = 7.
const PlatePoint kPoints[] = {{"C", {6.0, 10.0, 0.0}}, {"D", {6.0, 8.5, 0.0}},
                              {"E", {6.0, 7.0, 0.0}},  {"G", {8.0, 10.0, 0.0}},
                              {"H", {8.0, 8.5, 0.0}},  {"I", {8.0, 7.0, 0.0}}};

int nearest_node(const Mesh& mesh, const Vec3& target) {
  int best = -1;
  double best_distance = 0.0;
  for (int n = 0; n < static_cast<int>(mesh.nodes.size()); ++n) {
    const Vec3& x = mesh.nodes[n];
    const double d = std::hypot(x[0] - target[0], x[1] - target[1], x[2] - target[2]);
    if (best < 0 || d < best_distance - 1e-12) {
      best = n;
      best_distance = d;
    }
  }
  return best;
}

// The 2D model: every hexahedron (one layer, C3D8) becomes the CPS4 of its z = 0 face.
void to_plane_quads(Mesh& mesh) {
  for (MeshElement& element : mesh.elements) {
    element.type = "CPS4";
    element.nodes.resize(4);  // C3D8 nodes 1-4: the zeta = -1 face, counter-clockwise from +z
  }
  mesh.surfaces.clear();
  mesh.remove_unused_nodes();
}

BuildResult electric_plate(const BuilderParams& p, const ElementRegistry& registry) {
  const std::string fam = family(p, kPlateFamilies);
  const bool slit = p.choice("slit", {"no", "yes"}) == "yes";
  const double size = p.positive("size");
  const std::array<double, 3> k = {p.positive("k11"), p.positive("k22"), p.positive("k33")};
  const bool plane = fam == "CPS4";
  const std::string type = plane ? "C3D8" : "C3D20";

  const double x[4] = {0.0, 0.5 * (kSide - kSlitWidth), 0.5 * (kSide + kSlitWidth), kSide};
  const double y[4] = {0.0, 0.5 * (kSide - kSlitLength), 0.5 * (kSide + kSlitLength), kSide};
  auto divisions = [&](double length) {
    return std::max(1, static_cast<int>(std::lround(length / size)));
  };
  BuildResult r;
  std::vector<FaceRef> edges;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (slit && i == 1 && j == 1) continue;
      const int nx = i == 1 ? 1 : divisions(x[i + 1] - x[i]);
      const Block b = mesh_block(
          r.mesh, box_map({x[i], y[j], 0.0}, {x[i + 1] - x[i], y[j + 1] - y[j], kThickness}),
          {type, {nx, divisions(y[j + 1] - y[j]), 1}, {1, 1, 1}, "EALL"});
      if (i != 1) {
        const std::vector<FaceRef> side = b.side_faces(0, i == 0 ? -1 : 1);
        edges.insert(edges.end(), side.begin(), side.end());
      }
    }
  merge_coincident_nodes(r.mesh);
  if (plane) {
    to_plane_quads(r.mesh);
  } else {
    r.mesh.add_to_surface("EDGES", edges);
    apply_family(r.mesh, registry, fam, "EDGES");  // C3D28 along the two electrode edges
  }

  // Electrodes: every node on the through-thickness line of A (0, 7) and B (14, 7).
  const double tol = 1e-7 * kSide;
  auto line_at = [&](double px, double py) {
    return nodes_where(r.mesh, [&](const Vec3& q) {
      return std::abs(q[0] - px) < tol && std::abs(q[1] - py) < tol;
    });
  };
  const std::vector<int> a = line_at(0.0, 0.5 * kSide), b = line_at(kSide, 0.5 * kSide);

  std::string where;
  std::vector<int> points;
  for (const PlatePoint& point : kPoints) {
    const int n = nearest_node(r.mesh, point.target);
    char text[64];
    std::snprintf(text, sizeof text, "%s%s (%.4g, %.4g)", where.empty() ? "" : ", ", point.name,
                  r.mesh.nodes[n][0], r.mesh.nodes[n][1]);
    where += text;
    points.push_back(n);
  }
  char heading[128];
  std::snprintf(heading, sizeof heading, "SPEC 6.1 electric plate %g x %g x %g, %s, %s; ", kSide,
                kSide, kThickness, slit ? "central slit 0.02 x 5" : "no slit", fam.c_str());
  r.model = finish_model(r.mesh,
                         heading + std::string("-1 V at A (0, 7), 0 V at B (14, 7); points ") +
                             where + " (stand-in positions, docs/mesher.md)",
                         1.0, 0.0);
  Material& material = r.model.materials.front();
  material.young.reset();
  material.poisson.reset();
  material.electrical_conductivity = k;
  if (plane) r.model.sections.front().thickness = kThickness;

  add_node_set(r.model, "A", a);
  add_node_set(r.model, "B", b);
  for (std::size_t i = 0; i < points.size(); ++i)
    add_node_set(r.model, kPoints[i].name, {points[i]});
  add_node_set(r.model, "POINTS", points);
  Step step;
  step.name = "POTENTIAL";
  step.kind = StepKind::ElectricConduction;
  step.has_procedure = true;
  for (int n : a) step.boundaries.push_back({n, 9, -1.0, {}});
  for (int n : b) step.boundaries.push_back({n, 9, 0.0, {}});
  step.outputs = {print_request(OutputRequest::Kind::NodePrint, "POINTS", {"EPOT"}),
                  print_request(OutputRequest::Kind::NodePrint, "A", {"RECUR"}, true),
                  print_request(OutputRequest::Kind::NodePrint, "B", {"RECUR"}, true)};
  r.model.steps.push_back(step);
  if (slit) r.note = "the slit is a gap of one element width (0.02) left out of the mesh";
  return r;
}

}  // namespace

void add_electric_plate_builder(std::vector<BuilderInfo>& all) {
  all.push_back({"electric-plate",
                 "§6.1",
                 "Electric potential in a plate 14 x 14 x 0.5, optional central slit 0.02 x 5",
                 {family_param("C3D28", kPlateFamilies),
                  {"slit", "no", "central slit 0.02 x 5 across the line AB: no or yes"},
                  {"size", "0.5", "element length in the plate plane"},
                  {"k11", "1", "electrical conductivity along x"},
                  {"k22", "1", "electrical conductivity along y"},
                  {"k33", "1", "electrical conductivity along z"}},
                 electric_plate});
}

}  // namespace styk::mesher::detail
