// TElement: the base class of every element formulation (the thesis' TElement, made modern).
//
// A derived element supplies only what differs: its node layout and faces, DER (shape functions
// and natural derivatives) and its integration rules; BEE (strain-displacement) and DEE
// (constitutive matrix) have standard defaults. The base class does the rest once (template
// methods): Jacobian and its checks, stiffness, thermal load, consistent face loads, strains and
// stresses at the integration points. Formulations are stateless; one instance per type lives in
// the ElementRegistry and serves every element of that type.
//
// Formulations that are more than "B^T D B at the Gauss points" customise the template methods
// through three hooks instead of replacing them, so every template method (stiffness, thermal
// load, stresses, internal force) stays consistent with the others:
// - incompatible_mode_count() / incompatible_bee(): internal (incompatible-mode) strain fields,
//   condensed statically inside the element (C3D8I);
// - add_stabilisation(): a stiffness added after integration (hourglass control of C3D8R);
// - the section's ElementOptions::selective_volumetric switches on mean-dilatation B-bar for any
//   element (the volumetric strain is replaced by its element average).
//
// The material reaches the template methods as an ElementMaterial (styk/core/constitutive.hpp):
// the law is evaluated point by point there (temperature tables, material axes) and handed to
// the DEE hook as a MaterialPoint; elements never read the material's constants.
//
// Conventions
// - Natural coordinates (xi, eta, zeta) in [-1, 1]^3.
// - Strain/stress component order 11, 22, 33, 12, 13, 23 (Abaqus/CalculiX). B uses engineering
//   shear strains (gamma_12 = 2 eps_12); strains reported to users are tensor components.
// - Faces are numbered as Abaqus S1..S6: S1 zeta=-1, S2 zeta=+1, S3 eta=-1, S4 xi=+1, S5 eta=+1,
//   S6 xi=-1.
// - Plane elements (CPS/CPE) live in the x-y plane on natural (xi, eta) (zeta = 0); their faces
//   are their edges P1..P4, and they keep 3 dofs per node but stiffen only ux, uy
//   (active_dofs()). Trusses (T3D2) use xi only. Both customise the kinematics through
//   point_measure(), face_quadrature() and complete_strain(), which solids inherit unchanged.
// - Degrees of freedom per node (node_dofs()): 3 (ux, uy, uz) for continuum elements, 6 (ux, uy,
//   uz, rx, ry, rz: small rotations about the global axes, Abaqus/CalculiX dofs 4..6) for beams and
//   shells. Element matrices are dense in the element's own dof order: node 0 (its node_dofs()
//   components), node 1, ... A node of the model carries the most dofs any of its elements has.
// - Structural elements (beams) integrate section resultants, not a 3D stress field: they override
//   the template methods themselves (stiffness, eigenstrain_load, body_load, pressure_load,
//   strains_stresses, section_resultants), which are virtual for that reason; continuum elements
//   keep the defaults.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "styk/core/constitutive.hpp"
#include "styk/core/element_description.hpp"
#include "styk/core/model.hpp"

namespace styk {

// The largest number of dofs a node carries (3 translations + 3 rotations).
inline constexpr int kMaxNodeDofs = 6;
// Per node dof (index = dof - 1: ux, uy, uz, rx, ry, rz), whether an element stiffens it.
using DofSet = std::array<bool, kMaxNodeDofs>;

// Which of the element's rules to integrate with. Full is the element's standard rule, what the
// solver uses: for the reduced-integration types (C3D8R, C3D20R) both kinds are the reduced rule,
// because the element name fixes it.
enum class RuleKind { Full, Reduced };

// Per-section switches of the formulation (from *SOLID SECTION; passed by the solver).
struct ElementOptions {
  // Mean-dilatation B-bar (Styk-only TECHNIQUE=SELECTIVE): the volumetric part of B is replaced
  // by its average over the element, against volumetric locking as nu -> 0.5.
  bool selective_volumetric = false;
};

// What the element's section must give: nothing for solids, the out-of-plane thickness of plane
// elements (first data line of *SOLID SECTION, default 1, as in CalculiX), the cross-section area
// of trusses (required), a *BEAM SECTION for beams, a *SHELL SECTION for shells (its thickness
// in ElementGeometry::cross_section, offset and section points in the Section).
enum class SectionMeasure { None, Thickness, Area, Beam, Shell };

struct IntegrationRule {
  std::string label;         // e.g. "3x3x3 Gauss"
  std::vector<Vec3> points;  // natural coordinates
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};

// A face of the reference element: the element-local node indices on it (corners first, going
// round the face, then the other face nodes), and where it lies. A face on a coordinate plane of
// the reference cube or square gives that plane: axis 0/1/2 = xi/eta/zeta, value -1 or +1
// (hexahedra, the edges of quadrilaterals). Any other face (tetrahedra, wedges) has axis = -1:
// it is parametrised from its corners' natural coordinates (face_param.hpp: a triangle for 3
// corners, a bilinear quadrilateral for 4). Normals never depend on the node order: for axis >= 0
// they follow axis/value, for axis = -1 the side away from the element's natural centroid.
struct FaceDef {
  std::vector<int> nodes;
  int axis = 2;
  double value = -1.0;
};

// The element as placed in a model: its nodal coordinates (n x 3) and what to name it in messages.
struct ElementGeometry {
  Eigen::MatrixXd X;  // node coordinates, one row per element node
  Id id = 0;          // user element id
  SourceLoc where;    // the deck line that defined it
  // The section's geometric datum: thickness of plane elements, cross-section area of trusses
  // (SectionMeasure); ignored by solids. Must be positive where it is used.
  double cross_section = 1.0;
  // The element's section (the model owns it), for elements that need more than one number
  // (SectionMeasure::Beam: the *BEAM SECTION shape, dimensions and first section axis). May be
  // null for the others.
  const Section* section = nullptr;
  // Shells: the unit normal at each element node (one row per node), as the model resolves it
  // (normals averaged over the elements sharing a node, or given by *NORMAL). Empty: the element
  // takes the normals of its own geometry.
  Eigen::MatrixXd nodal_normals;
};

class TElement {
 public:
  virtual ~TElement() = default;

  // --- node layout -----------------------------------------------------------------------------
  virtual std::string name() const = 0;         // upper-case type name, e.g. "C3D20"
  virtual std::string description() const = 0;  // one line for `styk elements`
  virtual int node_count() const = 0;
  virtual const std::vector<Vec3>& natural_nodes() const = 0;
  virtual const std::vector<FaceDef>& faces() const = 0;  // faces()[0] is S1

  // Dofs per node in the element matrices: 3 (ux, uy, uz) or 6 (ux, uy, uz, rx, ry, rz).
  virtual int node_dofs() const { return 3; }
  // Which of the node dofs the element stiffens: a solver dof that no element stiffens is
  // inactive (plane elements: uz; planar beams: uz, rx, ry). Default: the three translations.
  // Entries beyond node_dofs() must be false.
  virtual DofSet active_dofs() const { return {true, true, true, false, false, false}; }
  // What the section must give (ElementGeometry::cross_section). Default: nothing.
  virtual SectionMeasure section_measure() const { return SectionMeasure::None; }
  // How many distributed-load labels P1..Pn *DLOAD may use on the element: its faces (uniform
  // pressure on face Sk) by default; beams: P1, P2 (force per length along section axes 1, 2).
  virtual int distributed_load_labels() const { return static_cast<int>(faces().size()); }

  // --- self-description (element_description.hpp): what the element models, how it is exported
  // and how the mesher makes it, so that nothing else keeps a table of type names ---------------
  // Default: inferred from the layout (no faces: Line; natural nodes all at zeta = 0 with faces of
  // at most 3 nodes: Planar; otherwise Solid). Axisymmetric elements must say so.
  virtual ElementForm form() const;
  // Default: the linear VTK cell of the element's corner nodes (corner_nodes()): 8 corners of a
  // solid a hexahedron, 6 a wedge, 4 a tetrahedron; 4 corners of a planar or axisymmetric element
  // a quadrilateral, 3 a triangle; 2 nodes of a line a line. Type 0 (no cell) otherwise, which
  // the VTU export refuses by name.
  virtual VtkCell vtk_cell() const;
  // How the mesher makes this type from another one; none by default.
  virtual std::optional<ElementConversion> conversion() const { return std::nullopt; }

  // --- DER: shape functions N (n) and natural derivatives dN (n x 3) at xi ----------------------
  virtual void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                   Eigen::Ref<Eigen::MatrixXd> dN) const = 0;

  // --- integration rules -----------------------------------------------------------------------
  virtual IntegrationRule rule(RuleKind kind) const = 0;
  // Gauss points per direction used to integrate over a face (pressure loads, nodal areas).
  virtual int face_rule_order() const = 0;

  // --- BEE: strain-displacement matrix (6 x 3n) from the Cartesian derivatives dNdx (n x 3) ----
  virtual void bee(const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                   Eigen::Ref<Eigen::MatrixXd> B) const;

  // --- DEE: the element's constitutive matrix from the material's 3D law at a point ------------
  // Default: the law itself (solids). Plane stress condenses sigma33 = sigma13 = sigma23 = 0,
  // trusses keep the uniaxial modulus.
  virtual void dee(const MaterialPoint& material, Matrix6d& D) const;

  // --- formulation hooks (defaults: none) ------------------------------------------------------
  // Number of internal incompatible-mode parameters (condensed statically inside the element).
  virtual int incompatible_mode_count() const { return 0; }
  // Their strain operator G (6 x incompatible_mode_count(), engineering shear) at natural point
  // xi of the element `g`, where det J = detJ. Must satisfy the patch test: integral of G dV = 0.
  virtual void incompatible_bee(const ElementGeometry& g, const Vec3& xi, double detJ,
                                Eigen::Ref<Eigen::MatrixXd> G) const;
  // Adds a stabilisation stiffness (e.g. hourglass control) to the integrated K (3n x 3n). It must
  // vanish on every affine displacement field so that the patch test still holds.
  virtual void add_stabilisation(const ElementGeometry& g, const Matrix6d& D,
                                 const ElementOptions& options, Eigen::MatrixXd& K) const;

  // --- kinematics hooks (defaults: a solid on (xi, eta, zeta)) --------------------------------
  // Cartesian derivatives dNdx (n x 3) at a point with shape-function values N and natural
  // derivatives dN, and its measure dV / (dxi deta dzeta): det J for solids (jacobian()), det J2
  // x thickness for plane elements, det J2 x 2 pi r for axisymmetric ones (r from N), |dx/dxi| x
  // area for trusses. Throws InputError like jacobian() on an inverted or degenerate element.
  virtual double point_measure(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                               const Eigen::Ref<const Eigen::MatrixXd>& dN,
                               Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const;
  // The strain operator B (6 x 3n) at a point with shape-function values N and Cartesian
  // derivatives dNdx. Default: bee(dNdx, B); axisymmetric elements add the hoop strain u_r / r,
  // which needs N and the geometry.
  virtual void strain_operator(const ElementGeometry& g, const Eigen::Ref<const Eigen::VectorXd>& N,
                               const Eigen::Ref<const Eigen::MatrixXd>& dNdx,
                               Eigen::Ref<Eigen::MatrixXd> B) const;
  // Integration points on a face: natural coordinates and, per point, the quadrature weight times
  // the area vector dA (its length is the area measure). On a face with axis >= 0 it points along
  // +face.axis (pressure_load() turns it outward by the sign of face.value); on a face with
  // axis = -1 it points out of the element. Solids: a face_rule_order()^2 Gauss rule on a cube
  // face, the face_param.hpp rule of that order on any other face; plane elements: a line rule
  // along the edge, times the thickness.
  virtual void face_quadrature(const ElementGeometry& g, const FaceDef& face,
                               std::vector<Vec3>& points,
                               std::vector<Eigen::Vector3d>& weighted_normals) const;
  // Completes the engineering strain at a point with what the formulation leaves to a stress
  // condition (plane stress: eps33 from sigma33 = 0), from the material's 3D law and thermal
  // strain at the point.
  virtual void complete_strain(const MaterialPoint& material,
                               Eigen::Matrix<double, 6, 1>& engineering) const;

  // --- section resultants (structural elements; none for continuum elements) -------------------
  // Stations of rule `kind`: the points along the element where section forces are reported.
  virtual int section_stations(RuleKind kind) const;
  // Section forces (stations x 3: SF1 axial, SF2 and SF3 transverse shear along section axes 2
  // and 1) and moments (stations x 3: SM1, SM2 bending about axes 1 and 2, SM3 torque) in the
  // displaced state u (m), with the thermal strain of the material's temperatures removed.
  virtual void section_resultants(const ElementGeometry& g, const ElementMaterial& material,
                                  RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                                  Eigen::MatrixXd& forces, Eigen::MatrixXd& moments) const;

  // --- template methods (virtual for structural elements; see the file comment) ----------------
  // Sizes: n = node_count(), m = node_dofs() * n element dofs (3n for continuum elements).
  // Cartesian derivatives dNdx (n x 3) and det J at xi. Throws InputError naming the element and
  // the point when det J <= 0 (inverted or degenerate element); `point` is 1-based for messages.
  double jacobian(const ElementGeometry& g, const Eigen::Ref<const Eigen::MatrixXd>& dN,
                  Eigen::Ref<Eigen::MatrixXd> dNdx, int point) const;

  // Stiffness K (m x m) with the given rule (incompatible modes condensed, stabilisation added).
  virtual void stiffness(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                         Eigen::MatrixXd& K, const ElementOptions& options = {}) const;

  // Equivalent nodal forces f (m) of the eigenstrains: integral of B^T (D eps_th - sigma0) dV,
  // with the thermal strain eps_th of `material` (its temperatures; zero without) and the initial
  // stress sigma0 at the integration points of `kind` (`initial_stress`: one row per point,
  // components 11, 22, 33, 12, 13, 23; may be null). A material without *EXPANSION is an
  // InputError where the temperature differs from the initial one.
  virtual void eigenstrain_load(const ElementGeometry& g, const ElementMaterial& material,
                                RuleKind kind, Eigen::VectorXd& f,
                                const ElementOptions& options = {},
                                const Eigen::MatrixXd* initial_stress = nullptr) const;
  // The thermal part alone from temperature changes `nodal_dT` (n; T - T_initial) of a constant
  // material: alpha dT (1, 1, 1, 0, 0, 0) interpolated with N.
  void thermal_load(const ElementGeometry& g, const Material& material, RuleKind kind,
                    const Eigen::Ref<const Eigen::VectorXd>& nodal_dT, Eigen::VectorXd& f,
                    const ElementOptions& options = {}) const;

  // Internal force f (m) = integral of B^T sigma dV (+ stabilisation forces) of the element in
  // the displaced state u (m), = K u - f_eigenstrain; what reactions are made of.
  virtual void internal_force(const ElementGeometry& g, const ElementMaterial& material,
                              RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                              Eigen::VectorXd& f, const ElementOptions& options = {},
                              const Eigen::MatrixXd* initial_stress = nullptr) const;
  void internal_force(const ElementGeometry& g, const Material& material, RuleKind kind,
                      const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::VectorXd& f,
                      const ElementOptions& options, const Eigen::VectorXd* nodal_dT) const;

  // Nodal forces f (m) of a body force per unit mass: integral of N^T density a(x) dV
  // (translational dofs; structural elements over their axis or mid-surface).
  virtual void body_load(const ElementGeometry& g, double density, RuleKind kind,
                         const BodyAcceleration& acceleration, Eigen::VectorXd& f) const;

  // Consistent nodal forces (m) of the distributed load of label P(face + 1) with magnitude p:
  // for continuum elements a uniform pressure on face `face` (0-based: 0 = S1), positive p
  // pushing into the element; beams: a force per length along section axis face + 1.
  virtual void pressure_load(const ElementGeometry& g, int face, double p,
                             Eigen::VectorXd& f) const;

  // Equivalent nodal areas A_i = integral of N_i dA over a face (SPEC eq. 2.9), one per element
  // node (zero off the face).
  void nodal_areas(const ElementGeometry& g, int face, Eigen::VectorXd& area) const;

  // Strains (tensor components) and stresses at the integration points of `kind`, one row each
  // (n_points x 6), from the element displacement vector u (m). The stress is
  // D (eps - eps_th) + sigma0 with the thermal strain of `material` and the initial stress
  // (`initial_stress`, may be null); the strain reported stays the total strain eps.
  // Incompatible modes are recovered from u before the strains are formed.
  virtual void strains_stresses(const ElementGeometry& g, const ElementMaterial& material,
                                RuleKind kind, const Eigen::Ref<const Eigen::VectorXd>& u,
                                Eigen::MatrixXd& strain, Eigen::MatrixXd& stress,
                                const ElementOptions& options = {},
                                const Eigen::MatrixXd* initial_stress = nullptr) const;
  // The same for a constant material with nodal temperature changes (n, T - T_initial; may be
  // null).
  void strains_stresses(const ElementGeometry& g, const Material& material, RuleKind kind,
                        const Eigen::Ref<const Eigen::VectorXd>& u, Eigen::MatrixXd& strain,
                        Eigen::MatrixXd& stress, const ElementOptions& options,
                        const Eigen::VectorXd* nodal_dT) const;

  // The global positions of the integration points of `kind` (n_points x 3).
  void point_positions(const ElementGeometry& g, RuleKind kind, Eigen::MatrixXd& x) const;
  // The volume each integration point of `kind` stands for, w_k times its measure (n_points).
  void point_volumes(const ElementGeometry& g, RuleKind kind, Eigen::VectorXd& dv) const;
  // The material's 3D law at each integration point of `kind`, in global axes.
  void point_laws(const ElementGeometry& g, const ElementMaterial& material, RuleKind kind,
                  std::vector<MaterialPoint>& laws) const;
};

// The element's corner nodes, ascending: the nodes whose natural point lies strictly between no
// two other nodes (vertices of the reference shape; mid-edge, face and interior nodes are not).
std::vector<int> corner_nodes(const TElement& element);
// The mean of the corners' natural coordinates: (0, 0, 0) for bricks and quadrilaterals,
// (1/4, 1/4, 1/4) for tetrahedra, (1/3, 1/3, 0) for wedges (where centroid values are taken).
Vec3 natural_centroid(const TElement& element);

// Gauss-Legendre points and weights on [-1, 1], n = 1..6.
void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights);
// Tensor-product Gauss rule nx x ny x nz, points ordered xi fastest, then eta, then zeta
// (the CalculiX/Abaqus integration-point numbering).
IntegrationRule gauss_rule(int nx, int ny, int nz);

}  // namespace styk
