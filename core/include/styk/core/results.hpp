// In-memory results of an analysis: what the solver produced and every consumer reads (HDF5
// writer, .dat writer, VTU export, renderer). One record per converged increment.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk {

using Tensor6 = std::array<double, 6>;  // 11, 22, 33, 12, 13, 23

// Contact state of one slave node of a contact pair at the end of an increment (docs/contact.md).
enum class ContactStatus : int { Open = 0, Stick = 1, Slip = 2 };
struct ContactNodeResult {
  int pair = 0;  // index into Model::contact_pairs
  int node = 0;  // slave node index
  ContactStatus status = ContactStatus::Open;
  double area = 0.0;              // nodal contact area (SPEC §2.5); 0 for a node-surface slave
  double pressure = 0.0;          // normal force / area, compressive positive (force if area 0)
  std::array<double, 2> shear{};  // tangential traction on the slave along t1, t2
  std::array<double, 2> slip{};   // accumulated slip of the slave relative to the master
  double gap = 0.0;               // normal opening; negative = penetration (round-off only)
  Vec3 normal{};                  // unit normal out of the slave, towards the master
  Vec3 t1{}, t2{};                // unit tangents, t2 = normal x t1
  Vec3 force{};                   // contact force on the slave node, global axes
  double fluid_pressure = 0.0;    // pressure penetration: the fluid's pressure on the node (0
                                  // outside the penetrated zone)
};
struct ContactPairResult {
  Vec3 force{};   // total contact force on the slave surface
  Vec3 moment{};  // its moment about the global origin
};
// A *PRESSURE PENETRATION at the end of an increment (docs/contact.md).
struct PenetrationResult {
  int pair = 0;           // index into Model::contact_pairs
  double pressure = 0.0;  // the fluid pressure of the increment
  int penetrated = 0;     // slave nodes in the penetrated zone
  int nodes = 0;          // slave nodes the fluid could reach (the pair's)
  bool leaked = false;    // the zone reaches a node of LEAK= (false without LEAK=)
};
// Global balance of a contact increment: applied loads + reactions = 0, and the contact forces on
// the two sides of every pair cancel.
struct ContactEquilibrium {
  bool valid = false;
  Vec3 applied{};                  // sum of the applied nodal forces (pressures included)
  Vec3 reactions{};                // sum of RF
  Vec3 contact_slave{};            // sum of the contact forces on slave nodes
  Vec3 contact_master{};           // ... on master nodes
  double relative_residual = 0.0;  // |applied + reactions| / max(|applied|, |reactions|, |contact|)
};

// A steady scalar field (heat or electric-conduction steps, docs/solver.md): nodal values, the
// reaction flows at prescribed nodes, and gradient and flux at the integration points (the layout
// of IncrementResult::ip_offset) with the flux averaged at the nodes (method I of SPEC §5).
// Flux = -k grad(phi): heat flux HFL, or current density ECD with the electric field -grad(phi).
struct ScalarFieldResult {
  enum class Kind { None, Temperature, Potential };
  Kind kind = Kind::None;        // None: a mechanical increment, every vector below empty
  std::vector<double> value;     // per node: NT (temperature) or EPOT (potential)
  std::vector<double> reaction;  // per node: RFL (heat flow) / RECUR (current), 0 where free
  std::vector<Vec3> gradient;    // per integration point: grad(phi)
  std::vector<Vec3> flux;        // per integration point: -k grad(phi)
  std::vector<Vec3> flux_nodal;  // per node: mean of the element-node (extrapolated) fluxes
};

// *SECTION PRINT (SOF, SOM, SOAREA): the force and moment the stresses transmit through an
// element-face surface (CalculiX: the nodal averaged stresses interpolated on the faces and
// integrated, the traction on the side the faces' elements are on; + normal force is tension).
struct SectionForces {
  std::string surface;
  std::string name;  // NAME= of the request
  Vec3 force{};      // total force, global
  Vec3 moment{};     // its moment about the global origin
  Vec3 centre{};     // the area centre
  Vec3 normal{};     // the mean unit normal (out of the faces' elements)
  Vec3 moment_about_centre{};
  double area = 0.0;
  double normal_force = 0.0;    // force . normal
  double shear_force = 0.0;     // |force - normal_force normal|
  double torque = 0.0;          // moment_about_centre . normal
  double bending_moment = 0.0;  // |moment_about_centre - torque normal|
};

struct IncrementResult {
  int step = 1;             // 1-based step number
  int increment = 1;        // 1-based increment within the step
  double step_time = 1.0;   // time within the step at the end of the increment
  double total_time = 1.0;  // time accumulated over the steps
  std::vector<Vec3> U;      // displacement per node
  std::vector<Vec3> RF;     // reaction force per node (zero where no dof is prescribed)
  // Rotation (rx, ry, rz; small, about the global axes) and reaction moment per node, in models
  // whose nodes carry rotations (beams); empty otherwise. Zero at nodes without rotations.
  std::vector<Vec3> UR;
  std::vector<Vec3> RM;
  // Section resultants of structural elements (beams) at their stations: element e owns
  // stations station_offset[e] .. station_offset[e+1]-1 (none for continuum elements). SF = SF1
  // axial force, SF2 and SF3 transverse shear forces along section axes 2 and 1; SM = SM1, SM2
  // bending moments about section axes 1 and 2, SM3 torque (Abaqus' names and order). All three
  // empty in models without structural elements.
  std::vector<int> station_offset;
  std::vector<Vec3> SF;
  std::vector<Vec3> SM;
  // Shells' transverse shear forces per unit length Q13 = ∫σ13 dz, Q23 = ∫σ23 dz in the lamina
  // axes (Abaqus' SF4, SF5 of a shell) at the same stations; zero at beam stations (a beam's
  // shear forces are SF2, SF3). Empty in models without shell elements.
  std::vector<std::array<double, 2>> SFQ;
  // Integration-point values: element e owns points ip_offset[e] .. ip_offset[e+1]-1.
  std::vector<int> ip_offset;
  std::vector<Tensor6> S;  // stress
  std::vector<Tensor6> E;  // strain, tensor components (eps_12, not gamma_12)

  // Recovered values (SPEC §5); empty when not computed. Element-node values follow the layout
  // of Model::connectivity (element e's node k at elements[e].first_node + k).
  std::vector<Tensor6> S_element_nodes;  // integration-point values extrapolated, unaveraged
  std::vector<Tensor6> E_element_nodes;
  std::vector<Tensor6> S_centroid;  // per element, evaluated at the element centre
  std::vector<Tensor6> E_centroid;
  std::vector<Tensor6> S_nodal_I;   // per node: method I, mean of the element-node values
  std::vector<Tensor6> S_nodal_II;  // per node: method II, mean of the centroid values
  std::vector<Tensor6> E_nodal_I;
  std::vector<Tensor6> E_nodal_II;

  // Energies, volumes and the error estimate, filled when an output request asks for them
  // (*EL PRINT ENER, ELSE, EVOL; *EL FILE ENER, THE, ERR); empty otherwise.
  std::vector<double> ENER;             // per integration point: strain energy density
  std::vector<Tensor6> THE;             // per integration point: thermal strain (tensor)
  std::vector<double> element_volume;   // per element (EVOL)
  std::vector<double> element_energy;   // per element: integral of ENER (ELSE)
  std::vector<double> ERR;              // per element: stress error estimate in % (docs)
  std::vector<SectionForces> sections;  // one per *SECTION PRINT request of the step
  // Per integration point: its global position, filled when some section has a cylindrical
  // *ORIENTATION (the .dat prints element results in the material axes there).
  std::vector<Vec3> ip_position;

  // Contact (models with *CONTACT PAIR): one entry per constrained slave node, in pair order;
  // per-pair totals indexed like Model::contact_pairs; the balance check.
  std::vector<ContactNodeResult> contact;
  std::vector<ContactPairResult> contact_pairs;
  ContactEquilibrium contact_equilibrium;
  std::vector<PenetrationResult> penetrations;  // one per *PRESSURE PENETRATION of the step

  // Scalar-field steps (*HEAT TRANSFER, *COUPLED THERMAL-ELECTRICAL): U, RF, S and E stay empty.
  ScalarFieldResult scalar;
};

struct Results {
  std::vector<IncrementResult> increments;
};

}  // namespace styk
