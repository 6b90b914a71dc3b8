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
// SPEC §6.1: the electric plate with and without slit.
void add_electric_plate_builder(std::vector<BuilderInfo>& all);

}  // namespace styk::mesher::detail
