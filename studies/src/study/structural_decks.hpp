// The CalculiX decks of the beam and plate problems (private to the studies): written as text and
// read by the .inp reader, so every run goes through *BEAM SECTION / *SHELL SECTION, *DLOAD and
// the whole input path, and each deck runs in ccx as it is.
#pragma once

#include <string>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/studies/study/families.hpp"

namespace styk::studies::detail {

// A cantilever along x, clamped at x = 0, under a uniform line load q along the section's axis 2
// (+y; *DLOAD P2): length L, RECT section width 1 (along axis 1, -z) x height h (along y), E, nu;
// `elements` beam elements of the family's type and *BEAM SECTION integration.
struct BeamDeck {
  double length = 1.0, height = 0.05, young = 1e7, poisson = 0.3, load = 1.0;
  int elements = 8;
};
std::string beam_deck(const ElementFamily& family, const BeamDeck& beam);

// Timoshenko beam theory (shear factor 5/6 of the RECT section): the tip deflection
// q L^4 / (8 E I) + q L^2 / (2 k G A), and the mean of the bending moment q (L - x)^2 / 2 over
// the root element 0 <= x <= L / elements.
double beam_tip_deflection(const BeamDeck& beam);
double beam_root_element_moment(const BeamDeck& beam);

// A quarter [0, a/2]^2 of the square plate of side a under uniform pressure q (*DLOAD P, +z),
// hard simply supported on x = 0 and y = 0 (w and the rotation along the edge), symmetric on
// x = a/2 and y = a/2; n x n elements of the family (STRI3: each cell cut into two triangles
// along its diagonal from its first corner). The plate centre is the deck's last node.
struct PlateDeck {
  double side = 1.0, thickness = 0.01, young = 10.92e5, poisson = 0.3, load = 1.0;
  int elements = 4;
};
std::string plate_deck(const ElementFamily& family, const PlateDeck& plate);

// The bending moment of element e averaged over its integration stations with the weights of
// its rule: the station value `component` picks from SM (beams: SM1; shells: M11 + M22).
double station_mean(const Model& model, const IncrementResult& result,
                    const ElementRegistry& registry, int e, double (*component)(const Vec3&));

}  // namespace styk::studies::detail
