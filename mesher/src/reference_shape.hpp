// Private to the mesher's conversions and splits: questions about an element type's reference
// shape, answered from its TElement (natural nodes, faces, shape functions) so that no table of
// type names is needed: which nodes lie on a face or an edge, how the reference cube turns a face
// into another, where a natural point lands on a placed element.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"
#include "styk/mesher/hex_topology.hpp"

namespace styk::mesher::detail {

class ReferenceShape {
 public:
  explicit ReferenceShape(const TElement& element);

  const TElement& element() const { return element_; }
  const std::vector<Vec3>& natural() const { return element_.natural_nodes(); }
  int face_count() const { return static_cast<int>(faces_.size()); }
  // The corner nodes of face f, in the order the face lists them (around the face).
  const std::vector<int>& face_corners(int f) const { return faces_[f]; }
  // The centroid of face f's corners, in natural coordinates.
  const Eigen::Vector3d& face_centre(int f) const { return centres_[f]; }

  // Whether natural point p lies on face f (in its plane and inside its corner polygon, to 1e-9).
  bool on_face(int f, const Eigen::Vector3d& p) const;
  // The element's corner nodes shared by every face through p: those of the smallest edge or face
  // containing p (one node at a corner); empty when p lies inside the element.
  std::vector<int> carrier_corners(const Eigen::Vector3d& p) const;
  // The face whose centre R carries `centre` (in the rotated numbering) onto; -1 if none.
  int face_at(const Eigen::Vector3d& centre) const;

  // The node of this type at natural point p, or -1.
  int node_at(const Eigen::Vector3d& p) const;

  // The proper rotations R of the reference cube (old = R new) that map the natural nodes onto
  // themselves and carry the centre of face `new_face` onto that of `old_face`; the first one
  // found, or false when the shape has none (it is not a cube, or the faces do not match).
  bool rotation_between(int new_face, int old_face, CubeRotation& R) const;
  // new local index -> old local index of an element renumbered by R.
  std::vector<int> renumbering(const CubeRotation& R) const;
  // The new face index of old face `old_face` after renumbering by R.
  int rotated_face(const CubeRotation& R, int old_face) const;

  // The point at natural coordinates xi of the element placed at `coords` (node coordinates in
  // this type's numbering), from its own shape functions.
  Eigen::Vector3d place(const std::vector<Vec3>& coords, const Eigen::Vector3d& xi) const;

 private:
  const TElement& element_;
  std::vector<std::vector<int>> faces_;  // corner nodes per face
  std::vector<Eigen::Vector3d> centres_;
};

Eigen::Vector3d natural_point(const Vec3& xi);
Eigen::Vector3d turn(const CubeRotation& R, const Eigen::Vector3d& x);

}  // namespace styk::mesher::detail
