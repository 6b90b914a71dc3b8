// The checks and the model edit the geometry objects share (geometry_objects.cpp: planes and
// lines; shell_surfaces.cpp: cylindrical panels and hemispheres): names and numbers checked
// before meshing, and the meshed object appended to the model as a new part with its section.
#pragma once

#include <optional>
#include <string>

#include "styk/core/beam_section.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/mesher/mesh.hpp"
#include "styk/mesher/shell_mesh.hpp"

namespace styk::gui::objects {

// A shell type of the registry (its form is Shell: S4 ... S9R, STRI3).
bool is_shell_type(const std::string& type, const ElementRegistry& registry);

// Refuses divisions outside 1 .. most, naming `what` (e.g. "side 1-2").
void check_divisions(int d, const std::string& what, int most);
// Refuses a grading (last / first element length) that is not a positive number.
void check_grading(double g, const std::string& what);
// Refuses a bad name or one whose element or node set exists already.
void check_object_names(const Model& model, const std::string& name, const std::string& what);
// With a material: refuses an unknown material and a `value` (thickness, area) that is not > 0.
void check_section(const Model& model, const std::string& material, double value,
                   const std::string& what);

// The mesh as a new part of `model` (element set and node set `name`), with a section when a
// material is given (`value`: thickness or area; `shell` / `beam`: a *SHELL SECTION with that
// OFFSET, a *BEAM SECTION).
Model append_object(const Model& model, mesher::Mesh& mesh, const std::string& name,
                    const std::string& material, double value,
                    std::optional<double> shell = std::nullopt,
                    std::optional<BeamSection> beam = std::nullopt);

// The mesher's spec of a shell object's input (PlaneInput, ShellSurfaceInput): its type, element
// set and divisions and gradings along u and v.
template <typename Input>
mesher::ShellMeshSpec shell_mesh_spec(const Input& in) {
  mesher::ShellMeshSpec spec;
  spec.type = to_upper(in.type);
  spec.divisions_u = in.divisions_u, spec.divisions_v = in.divisions_v;
  spec.grading_u = in.grading_u, spec.grading_v = in.grading_v;
  spec.elset = to_upper(in.name);
  return spec;
}

}  // namespace styk::gui::objects
