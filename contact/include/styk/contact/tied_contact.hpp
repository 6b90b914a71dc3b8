// *TIE (tied contact, CalculiX semantics): every slave node that lies within the position
// tolerance of the master surface is tied to the point of the master face it projects to,
// u_slave = sum_i N_i(p, q) u_i over the face's nodes, in each direction. Nodes of the slave
// surface that belong to the master surface too are not tied; nodes that reach no master face
// within the tolerance are reported as missed.
#pragma once

#include <utility>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"

namespace styk::contact {

struct TiedNode {
  int slave = 0;                               // node index
  std::vector<std::pair<int, double>> master;  // (node index, N_i), sum of N_i = 1
  Vec3 projection{};                           // the point on the master face
  double distance = 0.0;                       // from the slave node to it
};

struct TiedSurfaces {
  std::vector<TiedNode> tied;  // by slave node index
  std::vector<int> missed;     // slave nodes beyond the tolerance
  double tolerance = 0.0;      // the position tolerance that was used
};

// CalculiX's default position tolerance: 2.5 % of the typical element size, here the mean edge
// length of the master faces.
double default_tie_tolerance(const Model& model, const ElementRegistry& registry,
                             const Surface& master, const SourceLoc& where);

// Ties `tie`'s surfaces. A projection must lie within the face, or beyond its edge by no more
// than the default tolerance (CalculiX). Throws InputError at the *TIE for undefined surfaces.
TiedSurfaces tie_surfaces(const Model& model, const ElementRegistry& registry, const Tie& tie);

}  // namespace styk::contact
