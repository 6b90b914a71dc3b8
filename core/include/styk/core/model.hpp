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
  std::string type;           // upper-case element type name, e.g. "C3D20"
  int first_node = 0;         // offset into Model::connectivity
  int node_count = 0;
  int section = -1;           // index into Model::sections, -1 until a section claims it
  SourceLoc where;
};

struct NodeSet {
  std::string name;           // upper-case
  std::vector<int> nodes;     // node indices, sorted, unique
  SourceLoc where;
};

struct ElementSet {
  std::string name;           // upper-case
  std::vector<int> elements;  // element indices, sorted, unique
  SourceLoc where;
};

struct Material {
  std::string name;           // upper-case
  // *ELASTIC, TYPE=ISOTROPIC
  std::optional<double> young;
  std::optional<double> poisson;
  std::optional<double> density;
  // *EXPANSION: mean coefficient and the reference temperature (ZERO=)
  std::optional<double> expansion;
  double expansion_reference = 0.0;
  // *CONDUCTIVITY / *ELECTRICAL CONDUCTIVITY: diagonal k11, k22, k33 in global axes (isotropic:
  // three equal values); what steady heat / electric-conduction steps need (docs/solver.md).
  std::optional<std::array<double, 3>> conductivity;
  std::optional<std::array<double, 3>> electrical_conductivity;
  SourceLoc where;
};

struct Section {
  std::string elset;          // upper-case
  std::string material;       // upper-case
  int material_index = -1;
  std::optional<double> thickness;  // for plane and truss elements (first data line)
  // Styk-only: integrate the volumetric part of the strain selectively (B-bar, mean dilatation)
  // against volumetric locking in near-incompressible materials.
  bool selective_volumetric = false;
  SourceLoc where;
};

// Prescribed value of one degree of freedom (1-based dof as in the deck: 1..3 = ux, uy, uz;
// 11 = temperature, 9 = electric potential in scalar-field steps).
struct Boundary {
  int node = 0;               // node index
  int dof = 1;
  double value = 0.0;
  SourceLoc where;
};

struct ConcentratedLoad {
  int node = 0;               // node index
  int dof = 1;                // 1..3; *CFLUX 11 (heat flow), *CECUR 9 (current)
  double value = 0.0;
  SourceLoc where;
};

// Uniform pressure on face `face` (1..6 = S1..S6 / P1..P6) of an element; positive pushes into
// the element (Abaqus convention).
struct DistributedLoad {
  int element = 0;            // element index
  int face = 1;
  double magnitude = 0.0;
  SourceLoc where;
};

// One *NODE PRINT / *EL PRINT / *NODE FILE / *EL FILE / *CONTACT PRINT request.
struct OutputRequest {
  // ContactPrint: per slave node of every contact pair; vars CSTR, CDIS, CSTATUS (docs/input.md).
  enum class Kind { NodePrint, ElementPrint, NodeFile, ElementFile, ContactPrint };
  Kind kind = Kind::NodePrint;
  std::string set;                 // upper-case NSET= / ELSET=, empty = whole model
  std::vector<std::string> vars;   // upper-case: U, RF, S, E, ...
  bool totals = false;             // TOTALS=YES: also print the sum over the set
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
  int node = 0;               // node index
  double value = 0.0;
  SourceLoc where;
};

// What a step solves: the mechanical static problem or a steady scalar field (docs/solver.md,
// "Steady heat and electric potential"): *HEAT TRANSFER, STEADY STATE (temperature, dof 11) or
// the electric part of *COUPLED THERMAL-ELECTRICAL, STEADY STATE (potential, dof 9).
enum class StepKind { Static, HeatTransfer, ElectricConduction };

// Styk extension after Abaqus' *PRESSURE PENETRATION (step data, docs/input.md): a fluid
// pressure that enters the interface of the contact pair slave/master at the exposed slave nodes
// and acts on both faces wherever the penetrated zone reaches: the slave nodes connected to an
// exposed node through nodes that are open or carry a contact pressure below `critical`.
// CalculiX has no such keyword.
struct PressurePenetration {
  std::string slave, master;       // upper-case surfaces of a *CONTACT PAIR
  std::vector<int> exposed_slave;  // node indices (first data field: node or node set)
  std::vector<int> exposed_master; // second field
  double pressure = 0.0;           // fluid pressure at the end of the step (ramps like a load)
  double critical = 0.0;           // critical contact pressure (default 0: only where open)
  std::string leak_nset;           // Styk-only LEAK=: slave nodes on the far side of the seal
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
  // *PRESSURE PENETRATION: accumulated over the steps like the loads (a later definition for the
  // same pair replaces it; OP=NEW removes every earlier one).
  std::vector<PressurePenetration> penetrations;
  bool penetration_op_new = false;
  std::vector<OutputRequest> outputs;
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

struct Orientation {               // *ORIENTATION, NAME=, SYSTEM=
  std::string name;                // upper-case
  LocalAxes axes;
  SourceLoc where;
};

// *TRANSFORM: boundary conditions, loads and equation terms of the set's nodes act in `axes`.
struct Transform {
  std::string nset;                // upper-case
  LocalAxes axes;
  SourceLoc where;
};

// *EQUATION: sum of coefficient * u(node, dof) = 0, enforced exactly. terms[0] is the dependent
// dof (its coefficient is non-zero); at least two terms.
struct EquationTerm {
  int node = 0;                    // node index
  int dof = 1;                     // 1..3 (in the node's *TRANSFORM system if it has one)
  double coefficient = 0.0;
};
struct Equation {
  std::vector<EquationTerm> terms;
  SourceLoc where;
};

// One element face of a surface: face 1..n = S1..Sn of the element type (TElement::faces()).
struct SurfaceFace {
  int element = 0;                 // element index
  int face = 1;
};

struct Surface {                   // *SURFACE, NAME=, TYPE=ELEMENT|NODE
  enum class Kind { ElementFaces, Nodes };
  std::string name;                // upper-case
  Kind kind = Kind::ElementFaces;
  std::vector<SurfaceFace> faces;  // ElementFaces: sorted by (element, face), unique
  std::vector<int> nodes;          // Nodes: node indices, sorted, unique
  SourceLoc where;
};

struct Friction {                  // *FRICTION inside a *SURFACE INTERACTION
  enum class Kind { Isotropic, Anisotropic, Rough };  // Rough: no slip at all
  Kind kind = Kind::Isotropic;
  double mu = 0.0;                 // Isotropic: mu; Anisotropic: mu1 along local direction 1
  double mu2 = 0.0;                // Anisotropic: mu2 along local direction 2
  std::optional<double> stick_slope;  // CalculiX's 2nd field; Styk enforces stick exactly
  std::string orientation;         // Anisotropic: ORIENTATION= (Styk-only), upper-case
  SourceLoc where;
};

struct SurfaceInteraction {        // *SURFACE INTERACTION, NAME= (hard contact, exact)
  std::string name;                // upper-case
  std::optional<Friction> friction;  // none: frictionless
  SourceLoc where;
};

struct ContactPair {               // one data line of *CONTACT PAIR
  enum class Type { NodeToSurface, SurfaceToSurface };
  Type type = Type::NodeToSurface;
  std::string slave;               // upper-case surface names (Model::surfaces)
  std::string master;              // an element-face surface
  std::string interaction;         // Model::surface_interactions
  std::string adjust_nset;         // ADJUST=nset: move these slave nodes onto the master
  std::optional<double> adjust_tolerance;  // ADJUST=value: ... those closer than this
  // *CLEARANCE, VALUE=: initial gap (> 0) or interference (< 0) replacing the geometric one.
  std::optional<double> clearance;
  SourceLoc clearance_where;
  SourceLoc where;
};

// *TIE, CYCLIC SYMMETRY with its *CYCLIC SYMMETRY MODEL (CalculiX): the datum sector of a
// structure of `sectors` equal sectors about the axis a -> b. Every node of the slave surface is
// tied to the master node that the rotation about the axis by one sector angle (from the slave side
// to the master side) carries it to, u_master = Q u_slave (a static load that repeats in every
// sector: nodal diameter 0); nodes on the axis belong to both surfaces and move along it only.
struct CyclicSymmetry {
  std::string tie;                 // upper-case *TIE NAME=
  std::string slave, master;       // upper-case surface names (their nodes are tied)
  std::optional<double> position_tolerance;  // *TIE, POSITION TOLERANCE=
  int sectors = 0;                 // *CYCLIC SYMMETRY MODEL, N= (0 until one names this tie)
  int ngraph = 1;                  // NGRAPH= (CalculiX's output copies; read and written back)
  Vec3 a{}, b{};                   // the axis through a and b
  SourceLoc where;                 // the *TIE line
  SourceLoc model_where;           // the *CYCLIC SYMMETRY MODEL line
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

  std::map<std::string, NodeSet> nsets;        // by upper-case name
  std::map<std::string, ElementSet> elsets;    // by upper-case name
  std::vector<Material> materials;
  std::vector<Section> sections;
  std::vector<Boundary> boundaries;            // given outside any step: hold in every step
  std::vector<Step> steps;

  // Contact definitions and local systems (by upper-case name where named).
  std::map<std::string, Surface> surfaces;
  std::map<std::string, SurfaceInteraction> surface_interactions;
  std::vector<ContactPair> contact_pairs;
  std::map<std::string, Orientation> orientations;
  // Constraints and thermal state.
  std::vector<Transform> transforms;
  std::vector<Equation> equations;
  std::vector<CyclicSymmetry> cyclic_symmetries;
  std::vector<NodalTemperature> initial_temperatures;  // nodes not listed start at 0

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
