// The nodal normals of a model's curved shells (S4 .. S9R), resolved once for the whole mesh:
// at a node shared by shell elements whose own normals (the normal of each element's mid-surface
// interpolation there) lie within kNormalAveragingDegrees of each other, every element takes
// their average, so that a smooth shell meshed with facets stays smooth; where they differ by
// more (a fold: a box corner, a stiffener), each element keeps its own. *NORMAL lines replace
// the result for their element and node (Abaqus' rule: a given normal more than 160 degrees from
// the element's own is reversed, one between 20 and 160 degrees is used and warned of).
// docs/elements.md "Nodal normals of shells".
#pragma once

#include <string>
#include <vector>

#include "styk/core/element.hpp"
#include "styk/core/model.hpp"

namespace styk {

inline constexpr double kNormalAveragingDegrees = 20.0;

struct ShellNormals {
  // Per connectivity slot (Model::connectivity): the resolved unit normal of a curved shell's
  // node; {0, 0, 0} for the nodes of other elements and of shells whose own normal there does
  // not exist (a degenerate element, which then refuses itself by name).
  std::vector<Vec3> at_slot;
  std::vector<Id> fold_nodes;         // nodes whose shells keep their own normals, sorted
  std::vector<std::string> warnings;  // given normals far from their element's own
  bool any() const { return !at_slot.empty(); }
};

// `formulation` holds every element's TElement (null where unknown). Nothing is resolved (an
// empty at_slot) when the model has no curved shells.
ShellNormals resolve_shell_normals(const Model& model,
                                   const std::vector<const TElement*>& formulation);

// Whether an element's nodes carry normals: the degenerated shells (the flat Kirchhoff triangle
// STRI3 takes its plane's normal).
bool takes_nodal_normals(const TElement& element);

}  // namespace styk
