// The CPU side of a picture: the skins of the visible layers (built once) and, per frame, the
// vertex arrays the GL renderer draws (triangles, mesh edges, feature lines, the undeformed
// outline, line elements, node points) at a deformation scale, coloured by layer or by a scalar
// field.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/shell_normals.hpp"
#include "styk/render/color_scale.hpp"
#include "styk/render/field.hpp"
#include "styk/render/layers.hpp"
#include "styk/render/skin.hpp"

namespace styk::render {

class FaceShapes;

// One vertex of every primitive. Positions are relative to FrameGeometry::origin so that floats
// keep their precision far from the coordinate origin. t < 0: no field, draw `color`; otherwise
// the position on the colour scale (0..1).
struct Vertex {
  float position[3];
  float normal[3];  // outward unit normal of the face (zero for lines and points)
  float color[3];
  float t;
};

struct FrameGeometry {
  Vec3 origin{};
  std::vector<Vertex> face_vertices;
  // Indices into face_vertices, 3 per triangle, turning clockwise as seen from outside the
  // element the face belongs to (whatever the node order of the formulation's faces).
  std::vector<std::uint32_t> triangles;
  // Line pairs: the line elements (trusses, see is_line_element), one segment per pair of
  // consecutive nodes along the element, in the layer colour or with the field's t per node.
  // The outline below holds them undeformed too. Beams with a section are triangles (tubes) in
  // face_vertices instead, their undeformed axes in the outline.
  std::vector<Vertex> bars;
  std::vector<Vertex> edges;            // line pairs: every edge of every skin face, once
  std::vector<Vertex> features;         // line pairs: boundary, non-manifold and crease edges
  std::vector<Vertex> outline;          // line pairs: feature edges, bars of the undeformed shape
  std::vector<Vertex> points;           // the nodes of the visible elements
  std::vector<Vertex> ip_points;        // integration points coloured by their values
  std::array<float, 3> lower{0, 0, 0};  // bounds of everything above, relative to origin
  std::array<float, 3> upper{0, 0, 0};
  // Every layer's faces form closed, consistently oriented surfaces: each face edge is shared by
  // exactly two faces of the layer that run along it in opposite directions. The camera always
  // stays outside the model, so back faces of such a skin are hidden and need not be drawn.
  // False for open skins (left-out faces, shells, planar meshes) and inverted elements.
  bool closed = false;
};

// The visible part of a model: per visible layer, its elements after the filter, their skin and
// their nodes. Building it is the expensive, view-independent step.
class SkinModel {
 public:
  struct LayerSkin {
    std::string name;
    Rgb color;
    std::vector<int> elements;    // visible elements of the layer (after the filter)
    std::vector<SkinFace> faces;  // their skin
    std::vector<int> lines;       // the line elements among them (no faces: drawn as bars)
    std::vector<int> beams;       // the beams with a *BEAM SECTION: drawn as extruded sections
    std::vector<int> shells;      // the shells: drawn as surfaces with their thickness
    std::vector<int> nodes;       // their nodes, ascending
  };

  // Hidden layers are skipped. The model and the registry's formulations must outlive this object.
  SkinModel(const Model& model, const ElementRegistry& registry, const std::vector<Layer>& layers,
            const ElementFilter& filter);
  ~SkinModel();
  SkinModel(const SkinModel&) = delete;
  SkinModel& operator=(const SkinModel&) = delete;

  const Model& model() const { return model_; }
  const std::vector<LayerSkin>& layers() const { return layers_; }
  std::size_t face_count() const;
  std::vector<int> visible_nodes() const;  // union over the layers, ascending
  Vec3 centre() const { return centre_; }  // centre of the undeformed visible bounding box
  double size() const { return size_; }    // diagonal of that box
  const std::vector<const TElement*>& formulations() const { return formulations_; }
  // The curved shells' nodal normals the solver uses (averaged where the shell is smooth).
  const ShellNormals& shell_normals() const { return shell_normals_; }
  const FaceShapes& shapes() const { return *shapes_; }
  // The definition of drawn face `face` of element `element` (drawn_faces of its formulation).
  const FaceDef& face_def(int element, int face) const {
    return drawn_.at(formulations_[static_cast<std::size_t>(element)])
        .at(static_cast<std::size_t>(face));
  }

 private:
  const Model& model_;
  std::vector<const TElement*> formulations_;
  ShellNormals shell_normals_;
  std::map<const TElement*, std::vector<FaceDef>> drawn_;  // per distinct formulation
  std::unique_ptr<FaceShapes> shapes_;
  std::vector<LayerSkin> layers_;
  Vec3 centre_{};
  double size_ = 0.0;
};

struct GeometryRequest {
  const std::vector<Vec3>* displacement = nullptr;  // per node; nullptr = undeformed
  double scale = 0.0;                               // deformation scale factor
  // Per node rotations (the increment's UR; models with beams or shells): the drawn beam sections
  // and shell fibres turn by them times `scale`. nullptr: they keep their undeformed orientation.
  const std::vector<Vec3>* rotation = nullptr;
  const ScalarField* field = nullptr;  // nullptr = layer colours
  const ColorScale* colors = nullptr;  // required with a field
  // With a field that has values at some nodes only (contact output): leave out the faces it
  // does not cover instead of drawing them neutral grey.
  bool hide_undefined_faces = false;
  // Draw higher-order faces with a field on grids fine enough for the field (see geometry.cpp);
  // false: on their base grids (2 x degree per direction), e.g. to measure what refining costs.
  bool refine = true;
  bool points = true;                   // fill FrameGeometry::points
  bool beam_sections = true;            // draw beams as extruded sections (false: not at all)
  bool outline = false;                 // fill FrameGeometry::outline (undeformed)
  double feature_angle_degrees = 30.0;  // crease angle of feature lines
};

FrameGeometry build_geometry(const SkinModel& skin, const GeometryRequest& request);

// Whether `field` colours drawn face `face` (ScalarField::carries, with the face's nodes and its
// outward normal, undeformed, from its corners).
bool face_carries(const SkinModel& skin, const ScalarField& field, const SkinFace& face);

// Minimum and maximum of a field over the visible elements (their nodes where the field is
// defined, element nodes or elements, as the field is located). Shells coloured by point tensors
// count with the values drawn on their fibre (ScalarField::shell_fibre), beams with their
// sections' values, not with their nodal averages. {0, 0} when nothing is visible.
std::array<double, 2> field_range(const SkinModel& skin, const ScalarField& field);

}  // namespace styk::render
