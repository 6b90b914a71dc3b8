// *SHELL SECTION (CalculiX/Abaqus): ELSET, MATERIAL, optional OFFSET (a number, or SPOS / SNEG
// for +0.5 / -0.5); one data line: the thickness and, Abaqus' second field, the number of Simpson
// points through the thickness (odd, default 5). ORIENTATION, COMPOSITE and NODAL THICKNESS are
// refused by name. Also the rule which element takes which section keyword.
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {
namespace {

void refuse_unsupported_parameters(const KeywordLine& kw) {
  if (kw.find("ORIENTATION"))
    throw InputError(kw.where,
                     "ORIENTATION= on *SHELL SECTION is not supported (shells take isotropic "
                     "materials, which need no orientation)");
  if (kw.find("COMPOSITE"))
    throw InputError(kw.where,
                     "COMPOSITE on *SHELL SECTION is not supported (Styk's shells have one "
                     "layer of one material)");
  if (kw.find("NODAL THICKNESS"))
    throw InputError(kw.where,
                     "NODAL THICKNESS on *SHELL SECTION is not supported (Styk's shell "
                     "thickness is constant per section)");
}

double offset_value(const Parameter& p, const SourceLoc& where) {
  const std::string value = normalize_name(p.value);
  if (value == "SPOS") return 0.5;
  if (value == "SNEG") return -0.5;
  const double offset = real_value(p.value, "OFFSET= of *SHELL SECTION", where);
  if (!(std::abs(offset) <= 0.5))
    throw InputError(where, "OFFSET=" + p.value +
                                " of *SHELL SECTION: the reference surface must lie inside the "
                                "shell (-0.5 <= OFFSET <= 0.5, a fraction of the thickness)");
  return offset;
}

}  // namespace

std::string section_keyword(const Section& section) {
  if (section.beam) return "*BEAM SECTION";
  if (section.shell) return "*SHELL SECTION";
  return "*SOLID SECTION";
}

void check_section_kind(const Section& section, const Element& element,
                        const TElement& formulation) {
  const SectionMeasure measure = formulation.section_measure();
  const std::string wanted = measure == SectionMeasure::Beam    ? "*BEAM SECTION"
                             : measure == SectionMeasure::Shell ? "*SHELL SECTION"
                                                                : "*SOLID SECTION";
  const std::string given = section_keyword(section);
  if (given == wanted) return;
  const std::string what = measure == SectionMeasure::Beam    ? "a beam"
                           : measure == SectionMeasure::Shell ? "a shell"
                                                              : "neither a beam nor a shell";
  throw InputError(section.where, given + " of element set " + section.elset + " covers element " +
                                      std::to_string(element.id) + " (" + element.type + "), " +
                                      what + ": it takes a " + wanted);
}

void DeckReader::on_shell_section(const KeywordLine& kw) {
  refuse_unsupported_parameters(kw);
  Section section;
  section.elset = set_name(kw, "ELSET");
  section.material = normalize_name(kw.find("MATERIAL")->value);
  section.where = kw.where;
  ShellSection shell;
  if (const Parameter* offset = kw.find("OFFSET")) shell.offset = offset_value(*offset, kw.where);
  const std::optional<DataLine> line = next_data_line();
  if (!line)
    throw InputError(kw.where, "*SHELL SECTION needs a data line: thickness [, section points]");
  expect_fields(*line, 1, 2, "thickness [, number of section points through the thickness]");
  const double thickness = real_field(*line, 0, "thickness");
  if (!(thickness > 0.0))
    throw InputError(line->where, "the shell thickness must be positive, read " + line->fields[0]);
  section.thickness = thickness;
  if (line->fields.size() > 1 && !line->fields[1].empty()) {
    const double points = real_field(*line, 1, "number of section points");
    if (points != std::floor(points) || points < 3 || points > 15 ||
        static_cast<int>(points) % 2 == 0)
      throw InputError(line->where,
                       "the number of section points through the thickness must "
                       "be an odd integer from 3 to 15 (Simpson's rule), read " +
                           line->fields[1]);
    shell.section_points = static_cast<int>(points);
    shell.section_points_given = true;
  }
  if (std::optional<DataLine> extra = next_data_line())
    throw InputError(extra->where,
                     "*SHELL SECTION takes one data line (thickness [, section "
                     "points]); a second is not supported");
  section.shell = shell;
  model_.sections.push_back(std::move(section));
}

}  // namespace styk::inp
