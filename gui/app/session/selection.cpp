#include "session/selection.hpp"

#include <algorithm>

namespace styk::gui {
namespace {

bool face_less(const SurfaceFace& a, const SurfaceFace& b) {
  return a.element != b.element ? a.element < b.element : a.face < b.face;
}
bool face_equal(const SurfaceFace& a, const SurfaceFace& b) {
  return a.element == b.element && a.face == b.face;
}

// Merges `picked` into `current` (Add), removes it (Remove) or replaces it (Replace); both end
// sorted and unique.
template <typename T, typename Less, typename Equal>
void combine(std::vector<T>& current, std::vector<T> picked, SelectOp op, Less less, Equal equal) {
  std::sort(picked.begin(), picked.end(), less);
  picked.erase(std::unique(picked.begin(), picked.end(), equal), picked.end());
  std::vector<T> result;
  switch (op) {
    case SelectOp::Replace:
      result = std::move(picked);
      break;
    case SelectOp::Add:
      std::set_union(current.begin(), current.end(), picked.begin(), picked.end(),
                     std::back_inserter(result), less);
      break;
    case SelectOp::Remove:
      std::set_difference(current.begin(), current.end(), picked.begin(), picked.end(),
                          std::back_inserter(result), less);
      break;
  }
  current = std::move(result);
}

}  // namespace

std::string pick_kind_name(PickKind kind) {
  switch (kind) {
    case PickKind::Node:
      return "node";
    case PickKind::Element:
      return "element";
    case PickKind::Face:
      return "face";
  }
  return "?";
}

void Selection::set_kind(PickKind kind) {
  if (kind == kind_) return;
  kind_ = kind;
  clear();
}

void Selection::clear() {
  nodes_.clear();
  elements_.clear();
  faces_.clear();
}

void Selection::apply(SelectOp op, const std::vector<PickedItem>& items) {
  const auto less = [](int a, int b) { return a < b; };
  const auto equal = [](int a, int b) { return a == b; };
  std::vector<int> indices;
  std::vector<SurfaceFace> faces;
  for (const PickedItem& item : items) {
    if (item.kind != kind_) continue;
    if (kind_ == PickKind::Node)
      indices.push_back(item.node);
    else if (kind_ == PickKind::Element)
      indices.push_back(item.element);
    else
      faces.push_back({item.element, item.face});
  }
  switch (kind_) {
    case PickKind::Node:
      combine(nodes_, std::move(indices), op, less, equal);
      break;
    case PickKind::Element:
      combine(elements_, std::move(indices), op, less, equal);
      break;
    case PickKind::Face:
      combine(faces_, std::move(faces), op, face_less, face_equal);
      break;
  }
}

}  // namespace styk::gui
