// The model database: what an input deck (or the GUI) describes, validated and indexed.
// Plain data with a few lookup helpers; no Eigen here so every module can include it cheaply.
//
// Indices vs ids: the deck names nodes and elements by user ids (any positive integers); the model
// stores them densely and everything downstream works with 0-based indices. `node_index(id)` and
// `element_index(id)` translate.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "styk/core/diagnostics.hpp"

namespace styk {

using Id = std::int64_t;
using Vec3 = std::array<double, 3>;

// Upper-cases ASCII letters: set, material and keyword names are case-insensitive in the
// Abaqus/CalculiX language, so the model stores them upper-cased.
std::string to_upper(std::string s);

struct Element {
  Id id = 0;
  std::string type;    // upper-case element type name, e.g. "C3D20"
  int first_node = 0;  // offset into Model::connectivity
  int node_count = 0;
  int section = -1;  // index into Model::sections, -1 until a section claims it
  SourceLoc where;
};

struct NodeSet {
  std::string name;        // upper-case
  std::vector<int> nodes;  // node indices, sorted, unique
  SourceLoc where;
};

struct ElementSet {
  std::string name;           // upper-case
  std::vector<int> elements;  // element indices, sorted, unique
  SourceLoc where;
};

// One row of a material table: the constants and the temperature they hold at (CalculiX/Abaqus
// layout: the temperature is the field after the constants).
struct MaterialTableRow {
  std::vector<double> values;
  double temperature = 0.0;
};

// *ELASTIC, TYPE= and *EXPANSION, TYPE= (docs/input.md lists the constants of each).
enum class ElasticType { Isotropic, Orthotropic, EngineeringConstants, Anisotropic };
enum class ExpansionType { Isotropic, Orthotropic, Anisotropic };

struct Material {
  std::string name;  // upper-case
  // *ELASTIC, TYPE=ISOTROPIC with one line: the constant law. Unset when elastic_table holds it.
  std::optional<double> young;
  std::optional<double> poisson;
  std::optional<double> density;
  // *EXPANSION, TYPE=ISO with one line: the constant mean coefficient (unset when
  // expansion_table holds it), and the reference temperature (ZERO=) of the secant coefficients.
  std::optional<double> expansion;
  double expansion_reference = 0.0;
  // *ELASTIC beyond one isotropic line: orthotropic, engineering constants or anisotropic, and
  // tables over temperature (rows sorted by temperature, interpolated linearly, constant beyond
  // the ends). Evaluated by styk/core/constitutive.hpp, in the material axes of the section's
  // *ORIENTATION.
  ElasticType elastic_type = ElasticType::Isotropic;
  std::vector<MaterialTableRow> elastic_table;
  // *EXPANSION beyond one isotropic line: orthotropic (a11, a22, a33) or anisotropic (a11, a22,
  // a33, a12, a13, a23) coefficients and tables over temperature, as for elastic_table.
  ExpansionType expansion_type = ExpansionType::Isotropic;
  std::vector<MaterialTableRow> expansion_table;

  // Some elastic law is given (constant isotropic or a table).
  bool has_elasticity() const { return (young && poisson) || !elastic_table.empty(); }
  // Some expansion coefficient is given.
  bool has_expansion() const { return expansion.has_value() || !expansion_table.empty(); }
  // *CONDUCTIVITY / *ELECTRICAL CONDUCTIVITY: diagonal k11, k22, k33 in global axes (isotropic:
  // three equal values); what steady heat / electric-conduction steps need (docs/solver.md).
  std::optional<std::array<double, 3>> conductivity;
  std::optional<std::array<double, 3>> electrical_conductivity;
  SourceLoc where;
};

// *BEAM SECTION: a standard cross-section of beam elements (CalculiX/Abaqus; the shapes,
// dimensions and section constants are in styk/core/beam_section.hpp).
enum class BeamShape { Rect, Circ, Pipe, Box };
// How a beam's section terms are integrated along its axis (Styk-only INTEGRATION= of *BEAM
// SECTION): Reduced, the default, is Abaqus' rule (1 point for B21/B31, 2 for B22/B32); Full
// integrates exactly on a straight element (2 and 3 points) and locks in shear when slender.
enum class BeamIntegration { Reduced, Full };
struct BeamSection {
  BeamShape shape = BeamShape::Rect;
  std::vector<double> dimensions;  // first data line (beam_section.hpp)
  Vec3 direction{0.0, 0.0, -1.0};  // approximate first section axis n1 (second data line)
  bool direction_given = false;
  BeamIntegration integration = BeamIntegration::Reduced;
  bool integration_given = false;  // INTEGRATION= appeared on the keyword line
};

// *SHELL SECTION data beyond the thickness (kept in Section::thickness).
struct ShellSection {
  // OFFSET=: the reference surface (the nodes) lies this fraction of the thickness from the
  // mid-surface along the positive normal (Abaqus/CalculiX; SPOS = 0.5, SNEG = -0.5).
  double offset = 0.0;
  // Simpson points through the thickness (second field of the data line; odd, default 5).
  int section_points = 5;
  bool section_points_given = false;  // written back only when the deck gave it
};

// *NORMAL (TYPE=ELEMENT): the normal given for one node of one shell element. It replaces the
// normal Styk would average there (docs/input.md, *NORMAL).
struct UserNormal {
  int element = 0;   // element index
  int node = 0;      // node index (a node of that element)
  Vec3 direction{};  // global components as given (not normalised)
  SourceLoc where;
};

struct Section {
  std::string elset;     // upper-case
  std::string material;  // upper-case
  int material_index = -1;
  std::optional<double> thickness;    // for plane and truss elements (first data line)
  std::optional<BeamSection> beam;    // set for a *BEAM SECTION (beam elements)
  std::optional<ShellSection> shell;  // set for a *SHELL SECTION (shell elements)
  // Styk-only: integrate the volumetric part of the strain selectively (B-bar, mean dilatation)
  // against volumetric locking in near-incompressible materials.
  bool selective_volumetric = false;
  // ORIENTATION=: the *ORIENTATION whose axes are the material axes (upper-case; empty: global).
  std::string orientation;
  SourceLoc where;
};

// Prescribed value of one degree of freedom (1-based dof as in the deck: 1..3 = ux, uy, uz;
// 4..6 = rotations rx, ry, rz at nodes of beam elements; 11 = temperature, 9 = electric potential
// in scalar-field steps).
struct Boundary {
  int node = 0;  // node index
  int dof = 1;
  double value = 0.0;
  SourceLoc where;
  // *BOUNDARY, FIXED (step data): the dof keeps the value it had at the end of the previous step
  // (0 in the first step); `value` is unused.
  bool fixed = false;
};

struct ConcentratedLoad {
  int node = 0;  // node index
  int dof = 1;   // 1..3 forces, 4..6 moments; *CFLUX 11 (heat flow), *CECUR 9
  double value = 0.0;
  SourceLoc where;
};

// Uniform pressure on face `face` (1..6 = S1..S6 / P1..P6) of an element; positive pushes into
// the element (Abaqus convention).
struct DistributedLoad {
  int element = 0;  // element index
  int face = 1;
  double magnitude = 0.0;
  SourceLoc where;
};

// *DLOAD with GRAV or CENTRIF: a body force per unit mass on an element, times its *DENSITY.
// Gravity: acceleration `magnitude` along `direction` (unit). Centrifugal: magnitude = omega^2
// about the axis through `point` along `direction` (unit), acceleration omega^2 times the distance
// vector from the axis.
struct BodyLoad {
  enum class Kind { Gravity, Centrifugal };
  int element = 0;  // element index
  Kind kind = Kind::Gravity;
  double magnitude = 0.0;
  Vec3 point{};
  Vec3 direction{};
  SourceLoc where;
};

// The body acceleration field of one element: its gravity and centrifugal loads summed.
struct BodyAcceleration {
  struct Rotation {
    double omega_squared = 0.0;
    Vec3 point{};
    Vec3 axis{};  // unit
  };
  Vec3 gravity{0.0, 0.0, 0.0};
  std::vector<Rotation> rotations;

  bool empty() const {
    return rotations.empty() && gravity[0] == 0.0 && gravity[1] == 0.0 && gravity[2] == 0.0;
  }
  void add(const BodyLoad& load);
  // The acceleration at point x.
  Vec3 at(const Vec3& x) const;
};

// One *NODE PRINT / *EL PRINT / *NODE FILE / *EL FILE / *CONTACT PRINT / *SECTION PRINT request.
// As in CalculiX, a step without a request of some kind repeats the requests of that kind of the
// step before (styk/core/output_requests.hpp).
struct OutputRequest {
  // ContactPrint: per slave node of every contact pair; vars CSTR, CDIS, CSTATUS (docs/input.md).
  // SectionPrint: the force and moment on an element-face surface; vars SOF, SOM, SOAREA.
  enum class Kind { NodePrint, ElementPrint, NodeFile, ElementFile, ContactPrint, SectionPrint };
  Kind kind = Kind::NodePrint;
  std::string set;                // upper-case NSET= / ELSET= / SURFACE=, empty = whole model
  std::vector<std::string> vars;  // upper-case: U, RF, S, E, ...
  bool totals = false;            // TOTALS=YES: also print the sum over the set
  bool totals_only = false;       // TOTALS=ONLY: print the sum alone
  // GLOBAL=YES/NO: results in global axes or in the local systems (*TRANSFORM for nodal
  // variables, the section's *ORIENTATION for element ones). Unset: CalculiX's default, local for
  // *NODE PRINT and *EL PRINT, global for *NODE FILE and *EL FILE.
  std::optional<bool> global;
  // FREQUENCY= (FREQUENCYF= on *SECTION PRINT): output every n-th increment and the last one of
  // each step; 0: none. The last value given on any request holds from its step on (default 1).
  std::optional<int> frequency;
  std::string name;  // *SECTION PRINT, NAME= (as written)
  // *EL PRINT, POSITION= (Abaqus spelling): where S and E are printed. AveragedAtNodes prints
  // nodal method I (SPEC §5) for the nodes of the element set.
  enum class Position { IntegrationPoints, Centroidal, AveragedAtNodes };
  Position position = Position::IntegrationPoints;
  SourceLoc where;
};

enum class LinearSolverKind { Automatic, Cholmod, Iterative };

struct StaticProcedure {
  double initial_increment = 1.0;
  double total_time = 1.0;
  LinearSolverKind solver = LinearSolverKind::Automatic;  // *STATIC, SOLVER=
  // Minimum and maximum increment (data-line fields 3 and 4) when given.
  std::optional<double> min_increment;
  std::optional<double> max_increment;
  // *STATIC, DIRECT: fixed increments of initial_increment, no automatic increment control.
  bool fixed_increments = false;
  SourceLoc where;
};

// A temperature at one node: *INITIAL CONDITIONS, TYPE=TEMPERATURE or *TEMPERATURE.
struct NodalTemperature {
  int node = 0;  // node index
  double value = 0.0;
  SourceLoc where;
};

// What a step solves: the mechanical static problem or a steady scalar field (docs/solver.md,
// "Steady heat and electric potential"): *HEAT TRANSFER, STEADY STATE (temperature, dof 11) or
// the electric part of *COUPLED THERMAL-ELECTRICAL, STEADY STATE (potential, dof 9).
enum class StepKind { Static, HeatTransfer, ElectricConduction };

// *CHANGE SOLID SECTION inside a step: from this step on the elements of the section of `elset`
// take `material` (CalculiX: a linear step is solved from the total loads with the stiffness it
// has then).
struct SectionChange {
  std::string elset;        // upper-case; an element set named by a *SOLID SECTION
  std::string material;     // upper-case
  int material_index = -1;  // resolved when the deck is complete
  SourceLoc where;
};

// Styk extension after Abaqus' *PRESSURE PENETRATION (step data, docs/input.md): a fluid
// pressure that enters the interface of the contact pair slave/master at the exposed slave nodes
// and acts on both faces wherever the penetrated zone reaches: the slave nodes connected to an
// exposed node through nodes that are open or carry a contact pressure below `critical`.
// CalculiX has no such keyword.
struct PressurePenetration {
  std::string slave, master;        // upper-case surfaces of a *CONTACT PAIR
  std::vector<int> exposed_slave;   // node indices (first data field: node or node set)
  std::vector<int> exposed_master;  // second field
  double pressure = 0.0;            // fluid pressure at the end of the step (ramps like a load)
  double critical = 0.0;            // critical contact pressure (default 0: only where open)
  std::string leak_nset;            // Styk-only LEAK=: slave nodes on the far side of the seal
  SourceLoc where;
};

struct Step {
  std::string name;
  StepKind kind = StepKind::Static;
  StaticProcedure procedure;  // scalar steps use its times, solver choice and `where`
  bool has_procedure = false;
  // Boundary conditions and loads given inside this step. What an analysis step sees is the
  // accumulation over the steps up to it (OP=MOD semantics); OP=NEW resets (flags below).
  std::vector<Boundary> boundaries;
  std::vector<ConcentratedLoad> cloads;
  std::vector<DistributedLoad> dloads;
  std::vector<BodyLoad> body_loads;  // *DLOAD GRAV / CENTRIF (reset with dloads by OP=NEW)
  bool boundary_op_new = false;
  bool cload_op_new = false;
  bool dload_op_new = false;
  // *TEMPERATURE: accumulated over the steps like the loads (a later line for a node overrides);
  // OP=NEW returns every node to its initial temperature first.
  std::vector<NodalTemperature> temperatures;
  bool temperature_op_new = false;
  // Scalar steps: *CFLUX / *CECUR nodal flows and *DFLUX uniform face fluxes S1..S6 (into the
  // body positive), accumulated over the steps like the loads.
  std::vector<ConcentratedLoad> cfluxes;
  std::vector<DistributedLoad> dfluxes;
  bool cflux_op_new = false;
  bool dflux_op_new = false;
  std::vector<SectionChange> section_changes;
  // *PRESSURE PENETRATION: accumulated over the steps like the loads (a later definition for the
  // same pair replaces it; OP=NEW removes every earlier one).
  std::vector<PressurePenetration> penetrations;
  bool penetration_op_new = false;
  std::vector<OutputRequest> outputs;
  SourceLoc where;
};

// *INITIAL CONDITIONS, TYPE=STRESS: the stress at one integration point (of the element's
// standard rule, 1-based as in the .dat) before the first step; points not given start at 0.
struct InitialStress {
  int element = 0;  // element index
  int point = 1;
  std::array<double, 6> stress{};  // 11, 22, 33, 12, 13, 23
  SourceLoc where;
};

// A local coordinate system given by two points a, b (Abaqus/CalculiX *ORIENTATION, *TRANSFORM):
// Rectangular: local x along a (from the global origin), local y in the plane of a and b.
// Cylindrical: a and b lie on the axis; local 1 = radial, 2 = tangential, 3 = axial (a -> b).
enum class CoordinateSystem { Rectangular, Cylindrical };
struct LocalAxes {
  CoordinateSystem system = CoordinateSystem::Rectangular;
  Vec3 a{1.0, 0.0, 0.0};
  Vec3 b{0.0, 1.0, 0.0};
};

struct Orientation {  // *ORIENTATION, NAME=, SYSTEM=
  std::string name;   // upper-case
  LocalAxes axes;
  SourceLoc where;
};

// *TRANSFORM: boundary conditions, loads and equation terms of the set's nodes act in `axes`.
struct Transform {
  std::string nset;  // upper-case
  LocalAxes axes;
  SourceLoc where;
};

// *EQUATION: sum of coefficient * u(node, dof) = 0, enforced exactly. terms[0] is the dependent
// dof (its coefficient is non-zero); at least two terms.
struct EquationTerm {
  int node = 0;  // node index
  int dof = 1;   // 1..6 (in the node's *TRANSFORM system if it has one)
  double coefficient = 0.0;
};
struct Equation {
  std::vector<EquationTerm> terms;
  SourceLoc where;
};

// One element face of a surface: face 1..n = S1..Sn of the element type (TElement::faces()).
struct SurfaceFace {
  int element = 0;  // element index
  int face = 1;
};

struct Surface {  // *SURFACE, NAME=, TYPE=ELEMENT|NODE
  enum class Kind { ElementFaces, Nodes };
  std::string name;  // upper-case
  Kind kind = Kind::ElementFaces;
  std::vector<SurfaceFace> faces;  // ElementFaces: sorted by (element, face), unique
  std::vector<int> nodes;          // Nodes: node indices, sorted, unique
  SourceLoc where;
};

struct Friction {                                     // *FRICTION inside a *SURFACE INTERACTION
  enum class Kind { Isotropic, Anisotropic, Rough };  // Rough: no slip at all
  Kind kind = Kind::Isotropic;
  double mu = 0.0;                    // Isotropic: mu; Anisotropic: mu1 along local direction 1
  double mu2 = 0.0;                   // Anisotropic: mu2 along local direction 2
  std::optional<double> stick_slope;  // CalculiX's 2nd field; Styk enforces stick exactly
  std::string orientation;            // Anisotropic: ORIENTATION= (Styk-only), upper-case
  SourceLoc where;
};

// *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE= (CalculiX semantics, docs/input.md). Hard: exact
// contact (Lagrange multipliers). The others are penalty laws: the contact pressure is a function
// of the overclosure h (penetration, length), p(h).
struct PressureOverclosure {
  enum class Law { Hard, Linear, Exponential, Tied };
  Law law = Law::Hard;
  double slope = 0.0;               // Linear, Tied: K, pressure per length (> 0)
  std::optional<double> sigma_inf;  // Linear: tension for large clearances (CalculiX; kept)
  std::optional<double> c0;         // Linear: clearance factor; Exponential: c0 (length)
  double p0 = 0.0;                  // Exponential: pressure at zero clearance
  SourceLoc where;
  bool penalty() const { return law != Law::Hard; }
};

struct SurfaceInteraction {          // *SURFACE INTERACTION, NAME=
  std::string name;                  // upper-case
  std::optional<Friction> friction;  // none: frictionless
  SourceLoc where;
  PressureOverclosure behavior;  // *SURFACE BEHAVIOR (default: hard, exact)
};

struct ContactPair {  // one data line of *CONTACT PAIR
  // Mortar: segment-to-segment with dual multipliers (docs/contact.md, "Mortar contact").
  enum class Type { NodeToSurface, SurfaceToSurface, Mortar };
  Type type = Type::NodeToSurface;
  std::string slave;                       // upper-case surface names (Model::surfaces)
  std::string master;                      // an element-face surface
  std::string interaction;                 // Model::surface_interactions
  std::string adjust_nset;                 // ADJUST=nset: move these slave nodes onto the master
  std::optional<double> adjust_tolerance;  // ADJUST=value: ... those closer than this
  // *CLEARANCE, VALUE=: initial gap (> 0) or interference (< 0) replacing the geometric one.
  std::optional<double> clearance;
  SourceLoc clearance_where;
  SourceLoc where;
};

// *TIE (without CYCLIC SYMMETRY): tied contact. Every slave node within the position tolerance
// of a master face moves with the face point it projects to (u_slave = sum N_i u_i of that point).
struct Tie {
  std::string name;           // upper-case NAME=
  std::string slave, master;  // upper-case surfaces (slave: faces or nodes; master: faces)
  std::optional<double> position_tolerance;  // POSITION TOLERANCE=; unset: CalculiX's default
  bool adjust = true;  // ADJUST=YES (default): slave nodes are moved onto the master
  SourceLoc where;
};

// *COUPLING with *KINEMATIC or *DISTRIBUTING (CalculiX semantics, docs/input.md).
struct Coupling {
  enum class Kind { Kinematic, Distributing };
  std::string name;         // upper-case CONSTRAINT NAME=
  int reference_node = 0;   // node index of REF NODE=
  std::string surface;      // upper-case SURFACE= (faces; *KINEMATIC also nodes)
  std::string orientation;  // upper-case ORIENTATION=, empty: global axes
  Kind kind = Kind::Kinematic;
  // The dofs listed under *KINEMATIC (1..3: the coupled translations, rigid with the reference
  // node) or *DISTRIBUTING (4..6: the moments distributed with the forces), each 1-based.
  std::vector<int> dofs;
  SourceLoc where;
  SourceLoc kind_where;  // the *KINEMATIC / *DISTRIBUTING line
};

// *MPC: the linearised geometric constraints of CalculiX (which solves them geometrically
// nonlinear): BEAM keeps the distance of two nodes, STRAIGHT keeps the third and later nodes on
// the line of the first two, PLANE keeps the fourth and later nodes in the plane of the first
// three.
struct Mpc {
  enum class Type { Beam, Straight, Plane };
  Type type = Type::Beam;
  std::vector<int> nodes;  // node indices in deck order
  SourceLoc where;
};

// *PRE-TENSION SECTION, SURFACE=, NODE=: the surface's nodes are split; the elements of its faces
// take copies, tied to the originals across the section except along the normal, where the
// mean opening of the section equals dof 1 of the reference node (a *CLOAD on it is the bolt
// force, a *BOUNDARY the shortening).
struct PretensionSection {
  std::string surface;         // upper-case element-face surface
  int reference_node = 0;      // node index of NODE=
  std::optional<Vec3> normal;  // the data line; unset: the mean face normal
  SourceLoc where;
};

// *TIE, CYCLIC SYMMETRY with its *CYCLIC SYMMETRY MODEL (CalculiX): the datum sector of a
// structure of `sectors` equal sectors about the axis a -> b. Every node of the slave surface is
// tied to the master node that the rotation about the axis by one sector angle (from the slave side
// to the master side) carries it to, u_master = Q u_slave (a static load that repeats in every
// sector: nodal diameter 0); nodes on the axis belong to both surfaces and move along it only.
struct CyclicSymmetry {
  std::string tie;                           // upper-case *TIE NAME=
  std::string slave, master;                 // upper-case surface names (their nodes are tied)
  std::optional<double> position_tolerance;  // *TIE, POSITION TOLERANCE=
  int sectors = 0;        // *CYCLIC SYMMETRY MODEL, N= (0 until one names this tie)
  int ngraph = 1;         // NGRAPH= (CalculiX's output copies; read and written back)
  Vec3 a{}, b{};          // the axis through a and b
  SourceLoc where;        // the *TIE line
  SourceLoc model_where;  // the *CYCLIC SYMMETRY MODEL line
};

class Model {
 public:
  // Source deck path (for messages and default output names).
  std::string source;
  std::string heading;

  // Nodes
  std::vector<Id> node_ids;
  std::vector<Vec3> coords;
  // Elements; connectivity holds node indices, element e uses
  // connectivity[elements[e].first_node .. + node_count).
  std::vector<Element> elements;
  std::vector<int> connectivity;

  std::map<std::string, NodeSet> nsets;      // by upper-case name
  std::map<std::string, ElementSet> elsets;  // by upper-case name
  std::vector<Material> materials;
  std::vector<Section> sections;
  std::vector<UserNormal> normals;   // *NORMAL, in deck order (a later line for the same
                                     // element and node wins)
  std::vector<Boundary> boundaries;  // given outside any step: hold in every step
  std::vector<Step> steps;

  // Contact definitions and local systems (by upper-case name where named).
  std::map<std::string, Surface> surfaces;
  std::map<std::string, SurfaceInteraction> surface_interactions;
  std::vector<ContactPair> contact_pairs;
  std::map<std::string, Orientation> orientations;
  // Constraints and thermal state.
  std::vector<Transform> transforms;
  std::vector<Equation> equations;
  std::vector<Tie> ties;
  std::vector<Coupling> couplings;
  std::vector<Mpc> mpcs;
  std::vector<PretensionSection> pretension_sections;
  std::vector<CyclicSymmetry> cyclic_symmetries;
  std::vector<NodalTemperature> initial_temperatures;  // nodes not listed start at 0
  std::vector<InitialStress> initial_stresses;         // sorted by (element, point), unique

  int node_count() const { return static_cast<int>(node_ids.size()); }
  int element_count() const { return static_cast<int>(elements.size()); }
  const int* element_nodes(int e) const { return connectivity.data() + elements[e].first_node; }

  // -1 when absent.
  int node_index(Id id) const;
  int element_index(Id id) const;
  int material_index(const std::string& name) const;
  const NodeSet* find_nset(const std::string& name) const;
  const ElementSet* find_elset(const std::string& name) const;

  // Add a node / element, keeping the id maps current. Duplicate ids throw InputError at `where`.
  int add_node(Id id, const Vec3& x, const SourceLoc& where);
  int add_element(Id id, const std::string& type, const std::vector<int>& node_indices,
                  const SourceLoc& where);

 private:
  std::unordered_map<Id, int> node_by_id_;
  std::unordered_map<Id, int> element_by_id_;
};

}  // namespace styk
