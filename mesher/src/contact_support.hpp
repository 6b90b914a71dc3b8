// Shared pieces of the contact builders (SPEC §3.2, §4; private to the mesher): bodies with their
// own materials, the contact layers in the chosen element family with the contact face as S1 on
// both sides, surfaces, interactions, contact pairs and the contact output requests.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/geometry_maps.hpp"
#include "styk/mesher/mesh.hpp"

namespace styk::mesher::detail {

// One body of a contact model: the element set it covers and its material.
struct BodyMaterial {
  std::string elset;     // upper-case element set of the mesh
  std::string material;  // upper-case material name
  double young = 0.0;
  double poisson = 0.0;
  std::optional<double> expansion;  // *EXPANSION (mean coefficient, reference 0)
};

// The model of the mesh with one material and section per body; every element must belong to
// exactly one body (a builder bug otherwise: std::logic_error).
Model contact_model(const Mesh& mesh, const std::string& heading,
                    const std::vector<BodyMaterial>& bodies);

// Converts the mesh to the element family as its element describes (mesher::convert_elements):
// a layer type (C3D21, C3D28) on each surface's layer with the contact faces as its contact face
// (a C3D28 layer may grow to close itself, docs/mesher.md; the named surfaces keep exactly their
// faces), a whole-element type (C3D14) everywhere, nothing for a family without a conversion.
void convert_contact_layers(Mesh& mesh, const ElementRegistry& registry, const std::string& family,
                            const std::vector<std::string>& contact_surfaces);

// Writes mesh surfaces into the model as element-face *SURFACEs (S1 = face 0).
void add_surfaces(Model& model, const Mesh& mesh, const std::vector<std::string>& names);

// The --mu parameter: a coefficient >= 0 (0 = frictionless) or "rough" (no slip).
std::optional<Friction> friction_parameter(const BuilderParams& params, const std::string& name);
// The same for a value derived from parameter `name` (its "auto" resolved by the builder).
std::optional<Friction> friction_value(const BuilderParams& params, const std::string& name,
                                       const std::string& value);

// *SURFACE INTERACTION `name` with `friction` (nullopt: frictionless) and a node-to-surface
// *CONTACT PAIR slave -> master; `clearance` becomes its *CLEARANCE.
void add_contact(Model& model, const std::string& name, const std::string& slave,
                 const std::string& master, const std::optional<Friction>& friction,
                 std::optional<double> clearance = std::nullopt);

// *CONTACT PRINT of CSTR and CDIS, plus CSTATUS (Styk-only) unless the deck is meant for
// CalculiX too (families C3D8 and C3D20).
OutputRequest contact_print(const std::string& family);

// Faces of the mesh's element `e` lying on a side selected by a predicate of the face's corner
// coordinates (all four corners must satisfy it).
std::vector<FaceRef> faces_where(const Mesh& mesh, const std::vector<int>& elements,
                                 const std::function<bool(const Vec3&)>& on_side);

// Pressure `p` on the faces of a mesh surface (DistributedLoad, face = S1..S6).
void pressure_on(Step& step, const Mesh& mesh, const std::string& surface, double p);

std::string fmt_number(double v);

// A cross-section patch: (s, t) in [0, 1]^2 to a point of the plane z = 0.
using SectionPatch = std::function<Vec3(double s, double t)>;

// The O-grid of the quarter disc of unit radius (0..90 deg): [0] the core square [0, c]^2
// (s along x, t along y), [1] the ring block 0..45 deg and [2] 45..90 deg (s radial from the
// core edge to the circle, t along increasing angle); c = core half-width. Meshed with n x n
// (core) and m x n (rings) elements, the circle has 2n elements of equal angle.
std::vector<SectionPatch> quarter_o_grid(double core);
// The same O-grid over a sector 0..angle (at most 90 deg): the core is the kite O, A = (c, 0),
// M = c / cos(angle/2) at angle/2, B = c at `angle` (right angles at A and B; the square for
// 90 deg), the ring blocks run from A-M and M-B out to the arcs 0..angle/2 and angle/2..angle.
std::vector<SectionPatch> sector_o_grid(double core, double angle);

// A section patch extruded from z0 to z1 (zeta), scaled by radius(z) and turned by `angle` about
// z; s, t become xi, eta (the patch's orientation decides the handedness).
BlockMap prism(const SectionPatch& section, double z0, double z1,
               const std::function<double(double)>& radius, double angle = 0.0);

// The grading (last / first element length) of n geometric elements over `length` whose first
// element is `first` long: meshes that continue a graded region without a jump in size.
double continuing_grading(double first, double length, int n);

// Splits the merged mesh into two bodies at the faces between element set `body_a` and the rest
// (split_interface) and names the two facing surfaces `surface_a` (faces of body A) and
// `surface_b`. Returns the number of coincident node pairs.
int split_bodies(Mesh& mesh, const std::string& body_a, const std::string& surface_a,
                 const std::string& surface_b);

}  // namespace styk::mesher::detail
