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

// Prescribed value of one degree of freedom (1-based dof as in the deck: 1..3 = ux, uy, uz).
struct Boundary {
  int node = 0;               // node index
  int dof = 1;
  double value = 0.0;
  SourceLoc where;
};

struct ConcentratedLoad {
  int node = 0;               // node index
  int dof = 1;                // 1..3
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

// One *NODE PRINT / *EL PRINT / *NODE FILE / *EL FILE request.
struct OutputRequest {
  enum class Kind { NodePrint, ElementPrint, NodeFile, ElementFile };
  Kind kind = Kind::NodePrint;
  std::string set;                 // upper-case NSET= / ELSET=, empty = whole model
  std::vector<std::string> vars;   // upper-case: U, RF, S, E, ...
  bool totals = false;             // TOTALS=YES: also print the sum over the set
  SourceLoc where;
};

enum class LinearSolverKind { Automatic, Cholmod, Iterative };

struct StaticProcedure {
  double initial_increment = 1.0;
  double total_time = 1.0;
  LinearSolverKind solver = LinearSolverKind::Automatic;  // *STATIC, SOLVER=
  SourceLoc where;
};

struct Step {
  std::string name;
  StaticProcedure procedure;
  bool has_procedure = false;
  // Boundary conditions and loads given inside this step. What an analysis step sees is the
  // accumulation over the steps up to it (OP=MOD semantics); OP=NEW resets (flags below).
  std::vector<Boundary> boundaries;
  std::vector<ConcentratedLoad> cloads;
  std::vector<DistributedLoad> dloads;
  bool boundary_op_new = false;
  bool cload_op_new = false;
  bool dload_op_new = false;
  std::vector<OutputRequest> outputs;
  SourceLoc where;
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
