// *TIE, CYCLIC SYMMETRY and *CYCLIC SYMMETRY MODEL (CalculiX): the datum sector of a cyclic
// structure under a load that repeats in every sector. The surfaces may be defined after the
// *TIE; resolve_cyclic_references() checks them once the deck is complete.
#include <algorithm>
#include <cmath>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

void DeckReader::read_cyclic_tie(const KeywordLine& kw) {
  CyclicSymmetry tie;
  tie.tie = set_name(kw, "NAME");
  tie.where = kw.where;
  if (const Parameter* p = kw.find("POSITION TOLERANCE")) {
    const double value = real_value(p->value, "POSITION TOLERANCE", kw.where);
    if (!(value > 0.0))
      throw InputError(kw.where, "POSITION TOLERANCE must be positive, read " + p->value);
    tie.position_tolerance = value;
  }
  const std::optional<DataLine> line = single_data_line(kw, true, "slave surface, master surface");
  expect_fields(*line, 2, 2, "slave surface, master surface");
  for (std::size_t i = 0; i < 2; ++i)
    if (line->fields[i].empty())
      throw InputError(line->where,
                       std::string(i == 0 ? "the slave" : "the master") + " surface name is empty");
  tie.slave = normalize_name(line->fields[0]);
  tie.master = normalize_name(line->fields[1]);
  if (tie.slave == tie.master)
    throw InputError(line->where, "the slave and master surfaces of a cyclic *TIE must differ");
  model_.cyclic_symmetries.push_back(std::move(tie));
}

void DeckReader::on_cyclic_symmetry_model(const KeywordLine& kw) {
  if (const Parameter* check = kw.find("CHECK"); check && normalize_name(check->value) != "YES")
    throw InputError(kw.where, "CHECK=" + check->value +
                                   " is not supported: Styk's static cyclic symmetry needs the "
                                   "sector angle to be 360/N (CHECK=YES, the default)");
  CyclicSymmetry* tie = nullptr;
  if (const Parameter* name = kw.find("TIE")) {
    const std::string wanted = normalize_name(name->value);
    for (CyclicSymmetry& c : model_.cyclic_symmetries)
      if (c.tie == wanted) tie = &c;
    if (!tie)
      throw InputError(kw.where, "TIE=" + wanted +
                                     " names no cyclic *TIE defined before this line (a *TIE, "
                                     "CYCLIC SYMMETRY must precede its *CYCLIC SYMMETRY MODEL)");
  } else if (model_.cyclic_symmetries.size() == 1) {
    tie = &model_.cyclic_symmetries.front();
  } else {
    throw InputError(kw.where,
                     model_.cyclic_symmetries.empty()
                         ? kw.label() + " needs a preceding *TIE, CYCLIC SYMMETRY"
                         : kw.label() + " needs TIE= when several cyclic *TIEs are defined");
  }
  if (tie->sectors > 0)
    throw InputError(kw.where, "*TIE " + tie->tie + " already has a *CYCLIC SYMMETRY MODEL (at " +
                                   tie->model_where.str() + ")");
  const std::int64_t n = integer_value(kw.find("N")->value, "N", kw.where);
  if (n < 2 || n > 100000)
    throw InputError(kw.where,
                     "N=" + kw.find("N")->value + ": the number of sectors must be at least 2");
  tie->sectors = static_cast<int>(n);
  if (const Parameter* ngraph = kw.find("NGRAPH")) {
    const std::int64_t g = integer_value(ngraph->value, "NGRAPH", kw.where);
    if (g < 1 || g > n)
      throw InputError(kw.where, "NGRAPH=" + ngraph->value + " must lie between 1 and N");
    tie->ngraph = static_cast<int>(g);
  }
  const char* layout = "a1, a2, a3, b1, b2, b3 (two points on the axis of symmetry)";
  const std::optional<DataLine> line = single_data_line(kw, true, layout);
  expect_fields(*line, 6, 6, layout);
  const char* names[] = {"a1", "a2", "a3", "b1", "b2", "b3"};
  for (std::size_t i = 0; i < 3; ++i) {
    tie->a[i] = real_field(*line, i, std::string("coordinate ") + names[i]);
    tie->b[i] = real_field(*line, i + 3, std::string("coordinate ") + names[i + 3]);
  }
  const double length =
      std::hypot(tie->b[0] - tie->a[0], tie->b[1] - tie->a[1], tie->b[2] - tie->a[2]);
  const double scale = std::max({std::hypot(tie->a[0], tie->a[1], tie->a[2]),
                                 std::hypot(tie->b[0], tie->b[1], tie->b[2]), 1e-300});
  if (!(length > 1e-12 * scale))
    throw InputError(line->where, "points a and b coincide: they do not define an axis");
  tie->model_where = kw.where;
}

void DeckReader::resolve_cyclic_references() {
  for (const CyclicSymmetry& tie : model_.cyclic_symmetries) {
    if (tie.sectors == 0)
      throw InputError(
          tie.where, "cyclic *TIE " + tie.tie + " has no *CYCLIC SYMMETRY MODEL (N= and the axis)");
    for (const std::string* name : {&tie.slave, &tie.master})
      if (!model_.surfaces.count(*name))
        throw InputError(tie.where,
                         "*TIE names surface " + *name +
                             ", which is not defined; surfaces: " + some_names(model_.surfaces));
  }
}

}  // namespace styk::inp
