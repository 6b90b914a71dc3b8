// *TIE: tied contact between a slave and a master surface (CalculiX's default *TIE). The
// surfaces may be defined after the *TIE; resolve_constraint_references() checks them.
#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

void DeckReader::on_tie(const KeywordLine& kw) {
  for (const char* other : {"MULTISTAGE", "FLUID PERIODIC", "FLUID CYCLIC"})
    if (kw.find(other))
      throw InputError(kw.where, std::string("*TIE, ") + other +
                                     " is not supported; Styk reads *TIE as tied contact or, "
                                     "with CYCLIC SYMMETRY, as a cyclic symmetry tie");
  const std::string name = normalize_name(kw.find("NAME")->value);
  for (const Tie& other : model_.ties)
    if (other.name == name)
      throw InputError(kw.where,
                       "*TIE " + name + " is defined twice (first at " + other.where.str() + ")");
  for (const CyclicSymmetry& other : model_.cyclic_symmetries)
    if (other.tie == name)
      throw InputError(kw.where,
                       "*TIE " + name + " is defined twice (first at " + other.where.str() + ")");
  if (kw.find("CYCLIC SYMMETRY")) {
    if (kw.find("ADJUST"))
      throw InputError(kw.where, "ADJUST= belongs to a tied-contact *TIE, not to CYCLIC SYMMETRY");
    read_cyclic_tie(kw);
    return;
  }
  read_tied_contact(kw);
}

void DeckReader::read_tied_contact(const KeywordLine& kw) {
  Tie tie;
  tie.name = set_name(kw, "NAME");
  tie.where = kw.where;
  if (const Parameter* p = kw.find("POSITION TOLERANCE")) {
    const double value = real_value(p->value, "POSITION TOLERANCE", kw.where);
    if (!(value >= 0.0))
      throw InputError(kw.where, "POSITION TOLERANCE must not be negative, read " + p->value);
    // CalculiX: a tolerance below 1e-10 means "use the default" (2.5 % of the element size).
    if (value >= 1e-10) tie.position_tolerance = value;
  }
  if (const Parameter* p = kw.find("ADJUST")) {
    const std::string value = normalize_name(p->value);
    if (value != "YES" && value != "NO")
      throw InputError(kw.where, "ADJUST=" + p->value + " on *TIE: expected YES or NO");
    tie.adjust = value == "YES";
  }
  const std::optional<DataLine> line = single_data_line(kw, true, "slave surface, master surface");
  expect_fields(*line, 2, 2, "slave surface, master surface");
  tie.slave = normalize_name(line->fields[0]);
  tie.master = normalize_name(line->fields[1]);
  if (tie.slave.empty() || tie.master.empty())
    throw InputError(line->where, "*TIE needs a slave and a master surface name");
  if (tie.slave == tie.master)
    throw InputError(line->where, "the slave and master surfaces of a *TIE must differ");
  model_.ties.push_back(std::move(tie));
}

}  // namespace styk::inp
