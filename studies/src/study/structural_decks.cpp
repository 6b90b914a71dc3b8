#include "structural_decks.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "element_geometry.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::studies::detail {
namespace {

bool quadratic_beam(const std::string& type) { return type == "B32" || type == "B22"; }

// The plate grid: nodes at (i, j) of a (p n + 1)^2 grid, p the element order; serendipity
// elements have no cell-centre nodes. Node ids are row-major over the whole grid.
struct PlateGrid {
  int order = 1, n = 1;
  bool serendipity = false, triangles = false, centres = false;
  int points() const { return order * n + 1; }
  int id(int i, int j) const { return j * points() + i + 1; }
  bool exists(int i, int j) const { return !(serendipity && i % 2 == 1 && j % 2 == 1); }
};

PlateGrid plate_grid(const ElementFamily& family, int n) {
  const std::string& type = family.type();
  PlateGrid g;
  g.n = n;
  g.triangles = type == "STRI3";
  g.order = g.triangles || type[1] == '4' ? 1 : 2;
  g.serendipity = type[1] == '8';
  g.centres = type[1] == '9';
  return g;
}

void plate_elements(std::ostringstream& deck, const PlateGrid& g) {
  int id = 1;
  const int p = g.order;
  for (int b = 0; b < g.n; ++b)
    for (int a = 0; a < g.n; ++a) {
      const auto node = [&](int di, int dj) { return g.id(p * a + di, p * b + dj); };
      if (g.triangles) {
        deck << id++ << ", " << node(0, 0) << ", " << node(1, 0) << ", " << node(1, 1) << "\n";
        deck << id++ << ", " << node(0, 0) << ", " << node(1, 1) << ", " << node(0, 1) << "\n";
        continue;
      }
      deck << id++ << ", " << node(0, 0) << ", " << node(p, 0) << ", " << node(p, p) << ", "
           << node(0, p);
      if (p == 2)
        deck << ", " << node(1, 0) << ", " << node(2, 1) << ", " << node(1, 2) << ", "
             << node(0, 1);
      if (g.centres) deck << ", " << node(1, 1);
      deck << "\n";
    }
}

// Hard simple support on x = 0 (uz, rx) and y = 0 (uz, ry); symmetry on x = a/2 (ux, ry, rz)
// and y = a/2 (uy, rx, rz).
std::vector<int> plate_supports(int i, int j, int last) {
  std::vector<int> dofs;
  if (i == 0) dofs.insert(dofs.end(), {3, 4});
  if (j == 0) dofs.insert(dofs.end(), {3, 5});
  if (i == last) dofs.insert(dofs.end(), {1, 5, 6});
  if (j == last) dofs.insert(dofs.end(), {2, 4, 6});
  return dofs;
}

}  // namespace

std::string beam_deck(const ElementFamily& family, const BeamDeck& b) {
  const std::string& type = family.type();
  const bool quadratic = quadratic_beam(type);
  const int nodes = quadratic ? 2 * b.elements + 1 : b.elements + 1;
  std::ostringstream deck;
  deck.precision(17);
  deck << "*HEADING\nStyk study: cantilever of " << b.elements << " " << family.name
       << ", L = " << b.length << ", h = " << b.height << ", uniform load\n*NODE, NSET=NALL\n";
  for (int i = 0; i < nodes; ++i)
    deck << i + 1 << ", " << b.length * i / (nodes - 1) << ", 0., 0.\n";
  deck << "*NSET, NSET=ROOT\n1\n*NSET, NSET=TIP\n"
       << nodes << "\n*ELEMENT, TYPE=" << type << ", ELSET=BEAM\n";
  for (int e = 0; e < b.elements; ++e) {
    if (quadratic)
      deck << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << 2 * e + 3 << "\n";
    else
      deck << e + 1 << ", " << e + 1 << ", " << e + 2 << "\n";
  }
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n" << b.young << ", " << b.poisson << "\n";
  deck << "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT"
       << (family.integration.empty() ? "" : ", INTEGRATION=" + family.integration) << "\n"
       << "1., " << b.height << "\n";
  deck << "*BOUNDARY\nROOT, 1, 6\n*STEP\n*STATIC\n*DLOAD\nBEAM, P2, " << b.load << "\n*END STEP\n";
  return deck.str();
}

double beam_tip_deflection(const BeamDeck& b) {
  const double I = b.height * b.height * b.height / 12.0, A = b.height;
  const double kGA = 5.0 / 6.0 * b.young / (2.0 * (1.0 + b.poisson)) * A;
  const double L = b.length;
  return b.load * L * L * L * L / (8.0 * b.young * I) + b.load * L * L / (2.0 * kGA);
}

double beam_root_element_moment(const BeamDeck& b) {
  // (1/l) int_0^l q (L - x)^2 / 2 dx
  const double L = b.length, l = L / b.elements;
  return b.load * (L * L * L - (L - l) * (L - l) * (L - l)) / (6.0 * l);
}

std::string plate_deck(const ElementFamily& family, const PlateDeck& plate) {
  const PlateGrid g = plate_grid(family, plate.elements);
  const int last = g.points() - 1;
  const double half = plate.side / 2.0;
  std::ostringstream deck;
  deck.precision(17);
  deck << "*HEADING\nStyk study: quarter of a simply supported square plate, " << plate.elements
       << " x " << plate.elements << " " << family.name << ", t = " << plate.thickness
       << "\n*NODE\n";
  for (int j = 0; j <= last; ++j)
    for (int i = 0; i <= last; ++i)
      if (g.exists(i, j))
        deck << g.id(i, j) << ", " << half * i / last << ", " << half * j / last << ", 0.\n";
  deck << "*ELEMENT, TYPE=" << family.type() << ", ELSET=SHELL\n";
  plate_elements(deck, g);
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n"
       << plate.young << ", " << plate.poisson << "\n*SHELL SECTION, ELSET=SHELL, MATERIAL=M\n"
       << plate.thickness << "\n*BOUNDARY\n";
  for (int j = 0; j <= last; ++j)
    for (int i = 0; i <= last; ++i)
      if (g.exists(i, j))
        for (int dof : plate_supports(i, j, last))
          deck << g.id(i, j) << ", " << dof << ", " << dof << "\n";
  deck << "*STEP\n*STATIC\n*DLOAD\nSHELL, P, " << plate.load << "\n*END STEP\n";
  return deck.str();
}

double station_mean(const Model& model, const IncrementResult& result,
                    const ElementRegistry& registry, int e, double (*component)(const Vec3&)) {
  if (result.station_offset.size() <= static_cast<std::size_t>(e) + 1)
    throw InputError({model.source, 0}, "the solve recorded no section forces");
  const int first = result.station_offset[e], count = result.station_offset[e + 1] - first;
  const TElement& element = formulation_of(model, registry, e);
  // The rule with this many stations; its points come station by station (shells: three fibres
  // per surface point), so a station's weight is the sum of its points'.
  for (const RuleKind kind : {RuleKind::Reduced, RuleKind::Full}) {
    if (element.section_stations(kind) != count || count == 0) continue;
    const IntegrationRule rule = element.rule(kind);
    const int per_station = rule.size() / count;
    double sum = 0.0, weights = 0.0;
    for (int s = 0; s < count; ++s) {
      double w = 0.0;
      for (int k = 0; k < per_station; ++k) w += rule.weights[s * per_station + k];
      sum += w * component(result.SM[first + s]);
      weights += w;
    }
    return sum / weights;
  }
  throw InputError({model.source, 0}, "element " + std::to_string(model.elements[e].id) +
                                          ": no rule of its type has " + std::to_string(count) +
                                          " stations");
}

}  // namespace styk::studies::detail
