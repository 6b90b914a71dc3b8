// The SPEC §3.2 contact models, built with the mesher (shared by the verification tests and
// bench/contact). Header-only; C3D21 contact rows on both sides, matching nodes.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "contact_model_kit.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::test {

inline void add_pressure(Model& model, const std::string& surface, double p, int step = 0) {
  for (const SurfaceFace& f : model.surfaces.at(surface).faces)
    model.steps[step].dloads.push_back({f.element, f.face, p, {}});
}

// §3.2.3 two cantilevers (Zhong 1993): L = 1, h = 0.1 each, width 0.1, 40 x 2 x 1 elements each,
// E = 2e11, nu = 0, pressure 2e6 on the top, left ends clamped.
inline Model two_cantilevers_model(std::optional<Friction> friction) {
  mesher::Mesh mesh;
  const mesher::Block lower = add_box(mesh, {0, 0, 0}, {1, 0.1, 0.1}, {40, 1, 2}, "C3D20", "LOWER");
  const mesher::Block upper =
      add_box(mesh, {0, 0, 0.1}, {1, 0.1, 0.2}, {40, 1, 2}, "C3D20", "UPPER");
  mesh.add_to_surface("LOWER_TOP", lower.side_faces(2, 1));
  mesh.add_to_surface("UPPER_BOTTOM", upper.side_faces(2, -1));
  mesh.add_to_surface("LOAD", upper.side_faces(2, 1));
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "UPPER_BOTTOM");
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "LOWER_TOP");
  Model model = contact_model(mesh, {{"LOWER", 2e11, 0.0}, {"UPPER", 2e11, 0.0}});
  add_contact_pair(model, "UPPER_BOTTOM", "LOWER_TOP", "BEAMS", friction);
  add_pressure(model, "LOAD", 2e6);
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }), {1, 2, 3});
  return model;
}

// §3.2.4 punch on a half-space (Klarbring), quarter model: punch 10^3 (4 x 4 x 4), half-space
// 50^3 (4 x 4 under the punch, 5 graded 4:1 outwards, 8 graded 6:1 in depth), E = 2e5,
// nu = 0.3, bottom fixed, symmetry on x = 0 and y = 0, P = 1000 down at the punch's top corner
// node on the axis. An anisotropic friction names orientation friction.orientation (added here:
// local 1 = x, 2 = y).
inline Model punch_model(const Friction& friction) {
  mesher::Mesh mesh;
  const std::vector<std::pair<double, double>> xs = {{0, 10}, {10, 50}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const mesher::Block b =
          add_box(mesh, {xs[i].first, xs[j].first, -50}, {xs[i].second, xs[j].second, 0},
                  {i == 0 ? 4 : 5, j == 0 ? 4 : 5, 8}, "C3D20", "HALFSPACE",
                  {i == 0 ? 1.0 : 4.0, j == 0 ? 1.0 : 4.0, 1.0 / 6.0});
      if (i == 0 && j == 0) mesh.add_to_surface("HS_TOP", b.side_faces(2, 1));
    }
  mesher::merge_coincident_nodes(mesh);
  const mesher::Block p = add_box(mesh, {0, 0, 0}, {10, 10, 10}, {4, 4, 4}, "C3D20", "PUNCH");
  mesh.add_to_surface("PUNCH_BOTTOM", p.side_faces(2, -1));
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "PUNCH_BOTTOM");
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "HS_TOP");
  Model model = contact_model(mesh, {{"HALFSPACE", 2e5, 0.3}, {"PUNCH", 2e5, 0.3}});
  add_contact_pair(model, "PUNCH_BOTTOM", "HS_TOP", "PAD", friction);
  if (friction.kind == Friction::Kind::Anisotropic) {
    Orientation o;
    o.name = friction.orientation;
    model.orientations[o.name] = o;
  }
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }), {1});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }), {2});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[2] + 50) < 1e-9; }),
      {1, 2, 3});
  for (int n : nodes_where(model, [](const Vec3& x) {
         return std::abs(x[0]) < 1e-9 && std::abs(x[1]) < 1e-9 && std::abs(x[2] - 10) < 1e-9;
       }))
    model.steps[0].cloads.push_back({n, 3, -1000.0, {}});
  return model;
}

// A shrink-fit-sized model (SPEC §4.2 model A scale: 3072 elements, 153 contact pairs; a stand-in
// until the mesher's shrink-fit builder exists): quarter model, hollow shaft r 2-10 x 60 (12
// radial x 8 around x 28 axial), sleeve r 10-15 x 20 centred (12 x 8 x 4), E = 2e5, nu = 0.3,
// radial interference 0.02 by *CLEARANCE (the thermal step is not available yet), mu = 0.2,
// shaft end z = 0 held axially. Step 1: the fit; step 2: axial pressure `push` on the sleeve's top
// annulus in automatic increments starting at 0.25. The sleeve is held axially only by friction.
inline Model shrink_fit_model(double push) {
  constexpr double kPi = 3.14159265358979323846;
  mesher::Mesh mesh;
  auto ring = [&](double r0, double r1, double z0, double z1, int radial, int axial,
                  const std::string& elset) {
    const mesher::PatchMap profile =
        mesher::quad_map({{r0, 0, z0}, {r0, 0, z1}, {r1, 0, z1}, {r1, 0, z0}});
    mesher::BlockSpec spec;
    spec.type = "C3D20";
    spec.divisions = {axial, radial, 8};
    spec.elset = elset;
    return mesher::mesh_block(mesh, mesher::revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kPi / 2),
                              spec);
  };
  ring(2, 10, 0, 20, 12, 12, "SHAFT");
  const mesher::Block fit = ring(2, 10, 20, 40, 12, 4, "SHAFT");
  ring(2, 10, 40, 60, 12, 12, "SHAFT");
  mesher::merge_coincident_nodes(mesh);
  const mesher::Block sleeve = ring(10, 15, 20, 40, 12, 4, "SLEEVE");
  mesh.add_to_surface("SHAFT_FIT", fit.side_faces(1, 1));
  mesh.add_to_surface("SLEEVE_BORE", sleeve.side_faces(1, -1));
  mesh.add_to_surface("SLEEVE_TOP", sleeve.side_faces(0, 1));
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "SHAFT_FIT");
  mesher::convert_elements(mesh, test::shared_registry(), "C3D21", "SLEEVE_BORE");
  Model model = contact_model(mesh, {{"SHAFT", 2e5, 0.3}, {"SLEEVE", 2e5, 0.3}});
  Friction f;
  f.mu = 0.2;
  add_contact_pair(model, "SLEEVE_BORE", "SHAFT_FIT", "FIT", f);
  model.contact_pairs.back().clearance = -0.02;
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }), {1});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }), {2});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[2]) < 1e-9; }), {3});
  Step push_step = model.steps[0];
  push_step.name = "PUSH";
  push_step.procedure.initial_increment = 0.25;
  model.steps.push_back(push_step);
  add_pressure(model, "SLEEVE_TOP", push, 1);
  return model;
}

// §3.2.2 concentric cylinders (plane strain, length 1) on non-matching meshes: inner r 1-2
// (E = 10, nu = 0.3), outer r 2-3 (E = 20, nu = 0.2), internal pressure 5, external 3; quarter
// model, 3 radial x `around` x 1 axial C3D20 per cylinder. Slave: the outer cylinder's bore, as a
// `slave_type` contact layer (C3D21, C3D28; C3D20: the plain faces); master: the inner cylinder's
// C3D20 outer face; the pair `type` with a frictionless interaction named `interaction`. The
// divisions around differ, so the nodes coincide only at the angles both share.
inline Model nonmatching_cylinders_model(int inner_around, int outer_around,
                                         const std::string& slave_type,
                                         const std::string& interaction, ContactPair::Type type) {
  constexpr double kPi = 3.14159265358979323846;
  mesher::Mesh mesh;
  auto ring = [&](double r0, double r1, int around, const std::string& elset) {
    const mesher::PatchMap profile =
        mesher::quad_map({{r0, 0, 0}, {r0, 0, 1}, {r1, 0, 1}, {r1, 0, 0}});
    mesher::BlockSpec spec;
    spec.type = "C3D20";
    spec.divisions = {1, 3, around};
    spec.elset = elset;
    return mesher::mesh_block(mesh, mesher::revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kPi / 2),
                              spec);
  };
  const mesher::Block inner = ring(1.0, 2.0, inner_around, "INNER");
  const mesher::Block outer = ring(2.0, 3.0, outer_around, "OUTER");
  mesh.add_to_surface("INNER_OUT", inner.side_faces(1, 1));
  mesh.add_to_surface("OUTER_IN", outer.side_faces(1, -1));
  mesh.add_to_surface("P_IN", inner.side_faces(1, -1));
  mesh.add_to_surface("P_OUT", outer.side_faces(1, 1));
  if (slave_type != "C3D20")
    mesher::convert_elements(mesh, shared_registry(), slave_type, "OUTER_IN");
  Model model = contact_model(mesh, {{"INNER", 10.0, 0.3}, {"OUTER", 20.0, 0.2}});
  add_contact_pair(model, "OUTER_IN", "INNER_OUT", interaction, std::nullopt);
  model.contact_pairs.back().type = type;
  add_pressure(model, "P_IN", 5.0);
  add_pressure(model, "P_OUT", 3.0);
  fix(model, nodes_where(model, [](const Vec3&) { return true; }), {3});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }), {1});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }), {2});
  return model;
}

}  // namespace styk::test
