// SPEC §4.2 shrink fit as a quarter model built with the mesher library: a solid shaft Ø20 x 60
// (an O-grid: square core + two curved blocks per axial segment, so there is no degenerate element
// on the axis), a sleeve Ø20/Ø30 x 20 centred on it (z 20..40), coincident nodes on the interface
// r = 10 (node-to-node contact, C3D21 or C3D28 layers on both sides). Steel E = 2e5, nu = 0.3,
// alpha = 2e-5. Step 1 heats the shaft by dT = 100 (the sleeve stays at the initial temperature),
// which makes the interference; step 2 (optional) pushes the sleeve's top annulus axially.
// Symmetry ux = 0 on x = 0, uy = 0 on y = 0; the shaft end z = 0 is held axially; the sleeve is
// held axially by friction only. Header-only (shared by the verification test and bench/contact).
#pragma once

#include <cmath>
#include <string>

#include "contact_model_kit.hpp"
#include "hex_model_builder.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/merge.hpp"

namespace styk::test {

struct ShrinkFitMesh {
  std::string contact_type = "C3D21";  // the element of the two contact layers: C3D21 or C3D28
  int core = 4;       // elements across the square core (and per 45° of circumference)
  int radial = 3;     // shaft elements from the core to r = 10
  int fit = 8;        // axial elements under the sleeve
  int ends = 6;       // axial elements of each free shaft end (graded towards the sleeve)
  int sleeve = 3;     // sleeve elements across its wall
  double mu = 0.2;    // friction coefficient of the fit
  double push = 0.0;  // step 2 axial pressure on the sleeve's top annulus (0: no step 2)
  // Hold one sleeve node (outer rim, z = 30, on y = 0) axially: needed when mu = 0 (nothing else
  // holds the sleeve along the axis); statically determinate, so with a symmetric frictionless
  // fit its reaction is zero.
  bool hold_sleeve = false;
};

inline Model shrink_fit_thermal_model(const ShrinkFitMesh& spec) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double R = 10.0, a = 5.0;  // shaft radius, half-width of the square core
  mesher::Mesh mesh;
  auto shaft_segment = [&](double z0, double z1, int nz, double grading) {
    auto axial = [=](double xi) { return z0 + 0.5 * (xi + 1.0) * (z1 - z0); };
    mesher::BlockSpec spec_core;
    spec_core.type = "C3D20";
    spec_core.divisions = {spec.core, spec.core, nz};
    spec_core.grading = {1.0, 1.0, grading};
    spec_core.elset = "SHAFT";
    mesher::mesh_block(
        mesh,
        [=](const Vec3& xi) {
          return Vec3{a * 0.5 * (xi[0] + 1.0), a * 0.5 * (xi[1] + 1.0), axial(xi[2])};
        },
        spec_core);
    // The two curved blocks blend a straight core edge (inner) with an arc of r = R (outer);
    // xi = radial blend t, eta = position s along the edge (counter-clockwise), zeta = axial:
    // right-handed in both (t outward x s counter-clockwise = +z).
    mesher::BlockSpec spec_arc = spec_core;
    spec_arc.divisions = {spec.radial, spec.core, nz};
    std::vector<mesher::Block> arcs;
    for (int half = 0; half < 2; ++half)
      arcs.push_back(mesher::mesh_block(
          mesh,
          [=](const Vec3& xi) {
            const double t = 0.5 * (xi[0] + 1.0), s = 0.5 * (xi[1] + 1.0);
            const double angle = 0.25 * kPi * (half + s);
            const double ix = half == 0 ? a : a * (1.0 - s), iy = half == 0 ? a * s : a;
            return Vec3{(1.0 - t) * ix + t * R * std::cos(angle),
                        (1.0 - t) * iy + t * R * std::sin(angle), axial(xi[2])};
          },
          spec_arc));
    return arcs;
  };
  shaft_segment(0.0, 20.0, spec.ends, 1.0 / 3.0);
  const std::vector<mesher::Block> fit = shaft_segment(20.0, 40.0, spec.fit, 1.0);
  shaft_segment(40.0, 60.0, spec.ends, 3.0);
  mesher::merge_coincident_nodes(mesh);

  const mesher::PatchMap profile =
      mesher::quad_map({{R, 0, 20}, {R, 0, 40}, {15, 0, 40}, {15, 0, 20}});
  mesher::BlockSpec sleeve_spec;
  sleeve_spec.type = "C3D20";
  sleeve_spec.divisions = {spec.fit, spec.sleeve, 2 * spec.core};
  sleeve_spec.elset = "SLEEVE";
  const mesher::Block sleeve = mesher::mesh_block(
      mesh, mesher::revolve(profile, {0, 0, 0}, {0, 0, 1}, 0.0, kPi / 2), sleeve_spec);
  mesh.add_to_surface("SHAFT_FIT", fit[0].side_faces(0, 1));
  mesh.add_to_surface("SHAFT_FIT", fit[1].side_faces(0, 1));
  mesh.add_to_surface("SLEEVE_BORE", sleeve.side_faces(1, -1));
  mesh.add_to_surface("SLEEVE_TOP", sleeve.side_faces(0, 1));
  for (const char* surface : {"SHAFT_FIT", "SLEEVE_BORE"}) {
    if (spec.contact_type == "C3D28")
      mesher::convert_elements(mesh, test::shared_registry(), "C3D28", surface);
    else
      mesher::convert_elements(mesh, test::shared_registry(), "C3D21", surface);
  }
  Model model = contact_model(mesh, {{"SHAFT", 2e5, 0.3}, {"SLEEVE", 2e5, 0.3}});
  for (Material& m : model.materials) m.expansion = 2e-5;
  add_contact_pair(model, "SLEEVE_BORE", "SHAFT_FIT", "FIT", coulomb(spec.mu));
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[0]) < 1e-9; }), {1});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[1]) < 1e-9; }), {2});
  fix(model, nodes_where(model, [](const Vec3& x) { return std::abs(x[2]) < 1e-9; }), {3});
  if (spec.hold_sleeve)
    fix(model,
        nodes_where(model,
                    [](const Vec3& x) {
                      return std::abs(x[0] - 15.0) < 1e-9 && std::abs(x[1]) < 1e-9 &&
                             std::abs(x[2] - 30.0) < 1e-9;
                    }),
        {3});
  model.steps[0].name = "HEAT";
  for (int n : nodes_of(model, "SHAFT")) model.steps[0].temperatures.push_back({n, 100.0, {}});
  if (spec.push != 0.0) {
    Step push = model.steps[0];
    push.name = "PUSH";
    push.temperatures.clear();  // the shaft stays hot (temperatures carry over)
    push.procedure.initial_increment = 0.25;
    model.steps.push_back(push);
    for (const SurfaceFace& f : model.surfaces.at("SLEEVE_TOP").faces)
      model.steps[1].dloads.push_back({f.element, f.face, spec.push, {}});
  }
  return model;
}

}  // namespace styk::test
