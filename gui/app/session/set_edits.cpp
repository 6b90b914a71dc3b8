#include "session/set_edits.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include "session/input_checks.hpp"

namespace styk::gui {
namespace {

bool before(const SurfaceFace& a, const SurfaceFace& b) {
  return a.element != b.element ? a.element < b.element : a.face < b.face;
}
bool same(const SurfaceFace& a, const SurfaceFace& b) {
  return a.element == b.element && a.face == b.face;
}

// `members` changed by the picked items (both sorted, unique).
template <typename T, typename Less>
std::vector<T> combined(const std::vector<T>& members, const std::vector<T>& picked, Membership how,
                        Less less) {
  std::vector<T> out;
  switch (how) {
    case Membership::Keep:
      return members;
    case Membership::Replace:
      return picked;
    case Membership::Add:
      std::set_union(members.begin(), members.end(), picked.begin(), picked.end(),
                     std::back_inserter(out), less);
      return out;
    case Membership::Remove:
      std::set_difference(members.begin(), members.end(), picked.begin(), picked.end(),
                          std::back_inserter(out), less);
      return out;
  }
  return members;
}

void check_selection(const Model& model, const Selection& selection, PickKind wanted,
                     const std::string& what) {
  if (selection.kind() != wanted || selection.empty())
    refuse("a " + what + " takes picked " + pick_kind_name(wanted) +
           "s: pick them in the view (Select menu) first");
  for (int n : selection.nodes())
    if (n < 0 || n >= model.node_count())
      refuse("the selection is older than the model: pick again");
  for (int e : selection.elements())
    if (e < 0 || e >= model.element_count())
      refuse("the selection is older than the model: pick again");
  for (const SurfaceFace& f : selection.faces())
    if (f.element < 0 || f.element >= model.element_count() || f.face < 1)
      refuse("the selection is older than the model: pick again");
}

// Every reference by name to a set of `kind` from `from` to `to`.
void rename_references(Model& m, EntryKind kind, const std::string& from, const std::string& to) {
  using Kind = OutputRequest::Kind;
  const bool nodal = kind == EntryKind::NodeSet;
  if (kind == EntryKind::NodeSet || kind == EntryKind::ElementSet)
    for (Step& step : m.steps)
      for (OutputRequest& o : step.outputs) {
        const bool node_request = o.kind == Kind::NodePrint || o.kind == Kind::NodeFile;
        if (o.kind != Kind::ContactPrint && node_request == nodal && o.set == from) o.set = to;
      }
  if (kind == EntryKind::NodeSet) {
    for (Transform& t : m.transforms)
      if (t.nset == from) t.nset = to;
    for (ContactPair& p : m.contact_pairs)
      if (p.adjust_nset == from) p.adjust_nset = to;
  }
  if (kind == EntryKind::ElementSet)
    for (Section& s : m.sections)
      if (s.elset == from) s.elset = to;
  if (kind == EntryKind::Surface)
    for (ContactPair& p : m.contact_pairs) {
      if (p.slave == from) p.slave = to;
      if (p.master == from) p.master = to;
    }
}

// Moves the set `from` of the map to `to` with the new value.
template <typename Set>
void put(std::map<std::string, Set>& sets, const std::string& from, Set value) {
  sets.erase(from);
  const std::string name = value.name;
  sets[name] = std::move(value);
}

struct SectionChange {
  int element;
  int before;
  int after;
};

}  // namespace

std::string membership_name(Membership membership) {
  switch (membership) {
    case Membership::Keep:
      return "keep";
    case Membership::Replace:
      return "replace with the selection";
    case Membership::Add:
      return "add the selection";
    case Membership::Remove:
      return "remove the selection";
  }
  return "keep";
}

Membership membership_of(const std::string& name) {
  for (Membership m : {Membership::Keep, Membership::Replace, Membership::Add, Membership::Remove})
    if (membership_name(m) == name) return m;
  refuse("members: '" + name + "' is not one of keep, replace, add, remove");
}

std::unique_ptr<Command> set_edit_command(const Model& model, const Entry& entry,
                                          const SetEditInput& in, const Selection& selection) {
  const std::string what = entry.kind == EntryKind::NodeSet      ? "node set"
                           : entry.kind == EntryKind::ElementSet ? "element set"
                           : entry.kind == EntryKind::Surface    ? "surface"
                                                                 : "";
  if (what.empty()) refuse("this entry is not a set");
  check_name(in.name, "the " + what);
  const std::string old = entry.name;
  const std::string name = to_upper(in.name);
  const bool exists = entry.kind == EntryKind::NodeSet      ? model.nsets.count(old) > 0
                      : entry.kind == EntryKind::ElementSet ? model.elsets.count(old) > 0
                                                            : model.surfaces.count(old) > 0;
  if (!exists) refuse("no " + what + " " + old + " in the model");
  const bool taken = entry.kind == EntryKind::NodeSet      ? model.nsets.count(name) > 0
                     : entry.kind == EntryKind::ElementSet ? model.elsets.count(name) > 0
                                                           : model.surfaces.count(name) > 0;
  if (name != old && taken) refuse(what + " " + name + " exists already; choose another name");
  const bool members = in.membership != Membership::Keep;
  if (!members && name == old) refuse("nothing to change: give a new name or change the members");
  std::string text = "Edit " + what + " " + old;
  if (name != old) text = "Rename " + what + " " + old + " to " + name;

  if (entry.kind == EntryKind::NodeSet) {
    const NodeSet before_set = model.nsets.at(old);
    NodeSet after_set = before_set;
    after_set.name = name;
    if (members) {
      check_selection(model, selection, PickKind::Node, what);
      after_set.nodes = combined(before_set.nodes, selection.nodes(), in.membership, std::less<>());
    }
    if (after_set.nodes.empty()) refuse(what + " " + name + " would be empty; delete it instead");
    return make_model_edit(
        text,
        [old, after_set](Model& m) {
          put(m.nsets, old, after_set);
          rename_references(m, EntryKind::NodeSet, old, after_set.name);
        },
        [old, before_set, name](Model& m) {
          put(m.nsets, name, before_set);
          rename_references(m, EntryKind::NodeSet, name, old);
        },
        true);
  }
  if (entry.kind == EntryKind::Surface) {
    const Surface before_set = model.surfaces.at(old);
    Surface after_set = before_set;
    after_set.name = name;
    if (members) {
      if (before_set.kind != Surface::Kind::ElementFaces)
        refuse("surface " + old + " holds nodes, not faces: its members come from the deck");
      check_selection(model, selection, PickKind::Face, what);
      after_set.faces = combined(before_set.faces, selection.faces(), in.membership, before);
      after_set.faces.erase(std::unique(after_set.faces.begin(), after_set.faces.end(), same),
                            after_set.faces.end());
    }
    if (after_set.faces.empty() && after_set.nodes.empty())
      refuse(what + " " + name + " would be empty; delete it instead");
    return make_model_edit(
        text,
        [old, after_set](Model& m) {
          put(m.surfaces, old, after_set);
          rename_references(m, EntryKind::Surface, old, after_set.name);
        },
        [old, before_set, name](Model& m) {
          put(m.surfaces, name, before_set);
          rename_references(m, EntryKind::Surface, name, old);
        },
        true);
  }
  const ElementSet before_set = model.elsets.at(old);
  ElementSet after_set = before_set;
  after_set.name = name;
  std::vector<SectionChange> changes;
  if (members) {
    check_selection(model, selection, PickKind::Element, what);
    after_set.elements =
        combined(before_set.elements, selection.elements(), in.membership, std::less<>());
    int section = -1;
    for (int s = 0; s < static_cast<int>(model.sections.size()); ++s)
      if (model.sections[s].elset == old) section = s;
    if (section >= 0) {
      // The section follows its set: new members get it, members that leave lose it.
      for (int e : after_set.elements) {
        const int now = model.elements[e].section;
        if (now >= 0 && now != section)
          refuse("element " + std::to_string(model.elements[e].id) + " has the section on " +
                 model.sections[now].elset + "; an element belongs to one section only");
        if (now != section) changes.push_back({e, now, section});
      }
      for (int e : before_set.elements)
        if (!std::binary_search(after_set.elements.begin(), after_set.elements.end(), e))
          changes.push_back({e, section, -1});
    }
  }
  if (after_set.elements.empty()) refuse(what + " " + name + " would be empty; delete it instead");
  return make_model_edit(
      text,
      [old, after_set, changes](Model& m) {
        put(m.elsets, old, after_set);
        rename_references(m, EntryKind::ElementSet, old, after_set.name);
        for (const SectionChange& c : changes) m.elements[c.element].section = c.after;
      },
      [old, before_set, name, changes](Model& m) {
        put(m.elsets, name, before_set);
        rename_references(m, EntryKind::ElementSet, name, old);
        for (const SectionChange& c : changes) m.elements[c.element].section = c.before;
      },
      changes.empty());
}

}  // namespace styk::gui
