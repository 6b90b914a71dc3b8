// *BEAM SECTION (CalculiX/Abaqus): SECTION=RECT | CIRC | PIPE | BOX, first data line the
// dimensions, optional second data line the approximate first section axis (default (0, 0, -1)).
// Styk-only INTEGRATION=REDUCED|FULL chooses the rule along the axis. The CalculiX parameters
// OFFSET1, OFFSET2 (zero only), ORIENTATION and NODAL THICKNESS are named when refused.
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"
#include "styk/core/beam_section.hpp"

namespace styk::inp {
namespace {

BeamShape beam_shape(const std::string& text, const SourceLoc& where) {
  const std::string value = normalize_name(text);
  for (const BeamShape shape : {BeamShape::Rect, BeamShape::Circ, BeamShape::Pipe, BeamShape::Box})
    if (value == beam_shape_name(shape)) return shape;
  throw InputError(where, "*BEAM SECTION, SECTION=" + text +
                              " is not supported; Styk reads RECT, CIRC, PIPE and BOX (general "
                              "sections need *BEAM GENERAL SECTION, which Styk does not read)");
}

void refuse_unsupported_parameters(const KeywordLine& kw) {
  for (const char* offset : {"OFFSET1", "OFFSET2"})
    if (const Parameter* p = kw.find(offset))
      if (real_value(p->value, std::string(offset) + "= of *BEAM SECTION", kw.where) != 0.0)
        throw InputError(kw.where, std::string(offset) + "=" + p->value +
                                       ": section offsets are not supported (Styk's beam nodes "
                                       "lie on the section centroid)");
  if (kw.find("ORIENTATION"))
    throw InputError(kw.where,
                     "ORIENTATION= on *BEAM SECTION is not supported (beams take "
                     "isotropic materials, which need no orientation)");
  if (kw.find("NODAL THICKNESS"))
    throw InputError(kw.where,
                     "NODAL THICKNESS on *BEAM SECTION is not supported (Styk's "
                     "sections are constant along the beam)");
}

}  // namespace

void DeckReader::on_beam_section(const KeywordLine& kw) {
  refuse_unsupported_parameters(kw);
  Section section;
  section.elset = set_name(kw, "ELSET");
  section.material = normalize_name(kw.find("MATERIAL")->value);
  section.where = kw.where;
  BeamSection beam;
  beam.shape = beam_shape(kw.find("SECTION")->value, kw.where);
  if (const Parameter* integration = kw.find("INTEGRATION")) {  // Styk-only
    const std::string value = normalize_name(integration->value);
    if (value != "REDUCED" && value != "FULL")
      throw InputError(kw.where, "*BEAM SECTION, INTEGRATION=" + integration->value +
                                     " is not known; Styk reads REDUCED (default) or FULL");
    beam.integration = value == "FULL" ? BeamIntegration::Full : BeamIntegration::Reduced;
    beam.integration_given = true;
  }

  const std::array<int, 2> count = beam_dimension_count(beam.shape);
  const std::string dimensions = std::string("SECTION=") + beam_shape_name(beam.shape) + " (" +
                                 (beam.shape == BeamShape::Rect   ? "a, b"
                                  : beam.shape == BeamShape::Circ ? "d1 [, d2]"
                                  : beam.shape == BeamShape::Pipe ? "outer radius, thickness"
                                                                  : "a, b, t1, t2, t3, t4") +
                                 ")";
  const std::optional<DataLine> first = next_data_line();
  if (!first)
    throw InputError(kw.where,
                     "*BEAM SECTION needs a data line with the dimensions of " + dimensions);
  expect_fields(*first, count[0], count[1], "the dimensions of " + dimensions);
  for (std::size_t k = 0; k < first->fields.size(); ++k)
    beam.dimensions.push_back(real_field(*first, k, "dimension " + std::to_string(k + 1)));
  if (const std::string why = check_beam_section(beam); !why.empty())
    throw InputError(first->where, why);

  if (const std::optional<DataLine> second = next_data_line()) {
    expect_fields(*second, 3, 3, "the first section axis n1: x, y, z");
    for (std::size_t k = 0; k < 3; ++k)
      beam.direction[k] = real_field(*second, k, "component " + std::to_string(k + 1) + " of n1");
    const Vec3& d = beam.direction;
    if (!(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) > 0.0))
      throw InputError(second->where, "the first section axis n1 must not be zero");
    beam.direction_given = true;
    if (std::optional<DataLine> extra = next_data_line())
      throw InputError(extra->where,
                       "*BEAM SECTION takes two data lines (dimensions, first "
                       "section axis); a third is not supported");
  }
  section.beam = std::move(beam);
  // Elsets, materials, element types and the one-section-per-element rule are checked when the
  // deck is complete (DeckReader::assign_sections).
  model_.sections.push_back(std::move(section));
}

}  // namespace styk::inp
