// Registration of the builders by group (private to the mesher).
#pragma once

#include <vector>

#include "styk/mesher/builders.hpp"

namespace styk::mesher::detail {

// SPEC §2.1, §3.1.1-§3.1.4: beams.
void add_beam_builders(std::vector<BuilderInfo>& all);
// SPEC §2.4, §3.1.5-§3.1.8, §6.2: single element, plate, shells, cylinders, patch test.
void add_solid_builders(std::vector<BuilderInfo>& all);
// SPEC §3.2.1-§3.2.4: the contact tests.
void add_contact_builders(std::vector<BuilderInfo>& all);
// SPEC §4.2: the shrink fit.
void add_shrink_fit_builder(std::vector<BuilderInfo>& all);
// SPEC §4.3: the conical fit.
void add_conical_fit_builder(std::vector<BuilderInfo>& all);
// SPEC §4.4: the spline joint.
void add_spline_joint_builder(std::vector<BuilderInfo>& all);
// SPEC §4.5: the P3G polygon joint.
void add_p3g_joint_builder(std::vector<BuilderInfo>& all);
// SPEC §4.6: the bolted flange with gasket.
void add_bolted_flange_builder(std::vector<BuilderInfo>& all);
// SPEC §2.4: two stacked elements with a contact interface.
void add_stacked_elements_builder(std::vector<BuilderInfo>& all);
// SPEC §6.1: the electric plate with and without slit.
void add_electric_plate_builder(std::vector<BuilderInfo>& all);

}  // namespace styk::mesher::detail
