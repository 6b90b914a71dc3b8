// What the user picked in the 3D view: nodes, elements or element faces (one kind at a time, the
// pick mode), kept sorted and unique so a set made from it is ready for the Model. No Qt, no GL.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::gui {

enum class PickKind { Node, Element, Face };

// "node", "element", "face".
std::string pick_kind_name(PickKind kind);

// One picked entity: a node index, an element index, or an element index and its face (1-based,
// S1..Sn of the element type, as Model::SurfaceFace).
struct PickedItem {
  PickKind kind = PickKind::Node;
  int node = -1;
  int element = -1;
  int face = 0;
};

// How a pick changes the selection: plain click replaces, Shift adds, Ctrl removes.
enum class SelectOp { Replace, Add, Remove };

class Selection {
 public:
  explicit Selection(PickKind kind = PickKind::Node) : kind_(kind) {}

  PickKind kind() const { return kind_; }
  // Changing the kind empties the selection (a set holds one kind).
  void set_kind(PickKind kind);
  void clear();
  bool empty() const { return nodes_.empty() && elements_.empty() && faces_.empty(); }
  std::size_t size() const { return nodes_.size() + elements_.size() + faces_.size(); }

  // Items of another kind than kind() are ignored.
  void apply(SelectOp op, const std::vector<PickedItem>& items);

  const std::vector<int>& nodes() const { return nodes_; }          // node indices, ascending
  const std::vector<int>& elements() const { return elements_; }    // element indices, ascending
  const std::vector<SurfaceFace>& faces() const { return faces_; }  // by (element, face)

 private:
  PickKind kind_;
  std::vector<int> nodes_;
  std::vector<int> elements_;
  std::vector<SurfaceFace> faces_;
};

}  // namespace styk::gui
