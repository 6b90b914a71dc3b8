// Small models and synthetic results for the renderer tests. The results are filled the way the
// solver fills them (element-node values, centroid values, and the two nodal averages computed
// from those), from closed-form fields, so every expected number is known independently of the
// renderer.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/core/results.hpp"

namespace styk::render_test {

// Built-in elements plus the plug-ins of the build tree (C3D14, C3D21, C3D28). `libraries` must
// outlive the registry.
ElementRegistry make_test_registry(PluginLibraries& libraries);

struct TestScene {
  Model model;
  IncrementResult increment;
  bool has_results = false;
};

// "box":      C3D20 4 x 2 x 2 elements over [0,4] x [0,1] x [0,1], element sets LEFT (x < 2) and
//             RIGHT (x > 2), with results (fill_results).
// "box_mesh": the same mesh without results.
// "c3d21":    2 x 2 curved C3D21 elements (a quarter ring, S1 faces outward-bottom), results.
// "c3d28":    2 x 2 curved C3D28 elements, same shape, results.
// "contact_block": the solved contact model of contact_scene.hpp (element sets SLAB, BLOCK),
//             results from the solver (U, S, contact output).
// "plate_c3d20", "plate_c3d21", "plate_c3d28": 2 x 2 flat elements over [0,4] x [0,4] x [0,1]
//             (S1 faces at z = 0, seen from -z), U.x = plate_field (other results synthetic).
// "cylinders_c3d21": the SPEC §3.2.2 concentric cylinders (mesher builder `cylinders`, C3D21
//             contact layers), solved (contact_scene.hpp).
// Throws std::invalid_argument for another name.
TestScene make_scene(const std::string& name, const ElementRegistry& registry);

// Closed-form fields of the synthetic results at a point.
Vec3 displacement_at(const Vec3& x);  // U = (0.01 x, 0, -0.00125 x^2): U.x linear in x
Tensor6 stress_at(const Vec3& x);     // a bending-like stress state
// The jump added to the element values of element e (+/-20 on S11, alternating by element
// index), so unaveraged and averaged pictures differ visibly.
double element_jump(int e);

// Fills U, RF, S_element_nodes, S_centroid, S_nodal_I, S_nodal_II (and E_* = S / 2e5).
void fill_results(const Model& model, IncrementResult& increment);
// Fills the integration-point values S (and E = S / 2e5) and ip_offset: stress_at the points of
// each element's full rule, with the element's jump.
void fill_point_results(const Model& model, const ElementRegistry& registry,
                        IncrementResult& increment);

// The plates' U.x: (0.8 x + 0.6 y)^2, a quadratic the 8-, 9- and 16-node faces interpolate
// exactly, whose contours are straight lines at right angles to (0.8, 0.6).
double plate_field(const Vec3& x);

}  // namespace styk::render_test
