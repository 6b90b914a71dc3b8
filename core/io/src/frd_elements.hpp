// Which .frd element (cgx's element types) represents an element, and its nodes in the .frd's
// order, derived from the element's own VTK cell (TElement::vtk_cell()) so that plug-in elements
// write like built-in ones.
#pragma once

#include <vector>

#include "styk/core/element.hpp"

namespace styk::frd {

struct FrdCell {
  int type = 0;            // 1 he8, 2 pe6, 3 te4, 4 he20, 5 pe15, 6 te10, 7 tr3, 8 tr6,
                           // 9 qu4, 10 qu8, 11 be2, 12 be3; 0: none
  std::vector<int> nodes;  // element-local node indices in the .frd's order
};

FrdCell frd_cell(const TElement& element);

}  // namespace styk::frd
