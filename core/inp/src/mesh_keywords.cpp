// *HEADING, *NODE, *ELEMENT, *NSET, *ELSET.
#include <algorithm>
#include <vector>

#include "deck_reader.hpp"
#include "numbers.hpp"

namespace styk::inp {

namespace {
// Abaqus data lines hold at most 16 entries; a full line continues on the next one.
constexpr std::size_t kEntriesPerLine = 16;

// Calls visit(id) for first, first + step, ... <= last, without overflowing near the Id limit.
template <class Visit>
void for_each_generated(Id first, Id last, Id step, Visit&& visit) {
  for (Id id = first;; id += step) {
    visit(id);
    if (last - id < step) break;
  }
}

// The indices of the model's entities (count of them, id_of(index) their ids, index_of(id) the
// lookup) whose ids lie in the GENERATE range. A range longer than the model ("1, 2147483647") is
// matched against the model's ids instead of walked id by id, so no range takes longer than the
// model is large.
template <class IdOf, class IndexOf>
std::vector<int> generated_indices(int count, IdOf&& id_of, IndexOf&& index_of, Id first, Id last,
                                   Id step) {
  std::vector<int> out;
  if ((last - first) / step >= static_cast<Id>(count)) {
    for (int i = 0; i < count; ++i)
      if (const Id id = id_of(i); id >= first && id <= last && (id - first) % step == 0)
        out.push_back(i);
    return out;
  }
  for_each_generated(first, last, step, [&](Id id) {
    if (const int index = index_of(id); index >= 0) out.push_back(index);
  });
  return out;
}

std::string describe_range(Id first, Id last, Id step) {
  return std::to_string(first) + ".." + std::to_string(last) +
         (step == 1 ? "" : " in steps of " + std::to_string(step));
}

template <class Vec>
void sort_unique(Vec& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}
}  // namespace

void DeckReader::on_heading(const KeywordLine&) {
  // Heading lines are free text: read them raw, commas and all.
  while (const Card* card = source_.peek()) {
    if (card->is_keyword) break;
    if (!model_.heading.empty()) model_.heading += '\n';
    model_.heading += source_.next()->text;
  }
}

namespace {

// CalculiX reads a node's coordinates from fields 2-4 and defaults a missing or blank one to 0
// (a line with the id alone places the node at the origin); it ignores any later field. Abaqus
// reads fields 5-7 as the direction of the normal at the node (for the shells there). Styk reads
// that normal when it is not zero, and ignores later fields only when they are blank or zero, so
// that no number is lost to a stray comma unnoticed.
struct NodeLine {
  Vec3 x{0.0, 0.0, 0.0};
  Vec3 normal{0.0, 0.0, 0.0};
};

NodeLine node_line(const DataLine& line) {
  NodeLine out;
  for (std::size_t i = 1; i < line.fields.size(); ++i) {
    if (line.fields[i].empty()) continue;
    if (i <= 3) {
      out.x[i - 1] =
          real_field(line, i, std::string(1, static_cast<char>('x' + i - 1)) + " coordinate");
      continue;
    }
    if (i <= 6) {
      out.normal[i - 4] = real_field(line, i, "normal component n" + std::to_string(i - 3));
      continue;
    }
    if (real_field(line, i, "after the normal, ignored") != 0.0)
      throw InputError(line.where, "*NODE data line has " + std::to_string(line.fields.size()) +
                                       " fields, expected node id, x, y, z and optionally the "
                                       "normal nx, ny, nz; field " +
                                       std::to_string(i + 1) + " (" + line.fields[i] +
                                       ") would be ignored: check the commas of this line");
  }
  return out;
}

}  // namespace

void DeckReader::on_node(const KeywordLine& kw) {
  NodeSet* set = kw.find("NSET") ? &nset(set_name(kw, "NSET"), kw.where) : nullptr;
  while (std::optional<DataLine> line = next_data_line()) {
    if (files_.empty() || files_.back() != line->where.file) files_.push_back(line->where.file);
    const Id id = id_field(*line, 0, "node id");
    const NodeLine read = node_line(*line);
    const int existing = model_.node_index(id);
    if (existing >= 0) {
      const auto [f, l] = node_lines_[existing];
      throw InputError(line->where, "node " + std::to_string(id) + " is defined twice (first at " +
                                        SourceLoc{files_[f], l}.str() + ")");
    }
    const int index = model_.add_node(id, read.x, line->where);
    if (read.normal != Vec3{0.0, 0.0, 0.0})
      node_normals_.push_back({index, read.normal, line->where});
    node_lines_.emplace_back(static_cast<int>(files_.size()) - 1, line->where.line);
    if (set) set->nodes.push_back(index);
  }
  if (set) sort_unique(set->nodes);
}

void DeckReader::on_element(const KeywordLine& kw) {
  const std::string type = normalize_name(kw.find("TYPE")->value);
  const TElement* formulation = registry_.find(type);
  if (!formulation) {
    std::string known;
    for (const std::string& name : registry_.names()) known += (known.empty() ? "" : ", ") + name;
    std::string message =
        "unknown element type " + type + "; registered types: " + (known.empty() ? "none" : known);
    if (!registry_.searched_paths.empty())
      message += " (plug-ins searched in " + registry_.searched_paths + ")";
    throw InputError(kw.where, message);
  }
  const auto n = static_cast<std::size_t>(formulation->node_count());
  ElementSet* set = kw.find("ELSET") ? &elset(set_name(kw, "ELSET"), kw.where) : nullptr;
  std::vector<int> nodes;
  while (std::optional<DataLine> line = next_data_line()) {
    // Continuation: a line ending with ',' or holding the maximum 16 entries goes on.
    bool more = line->trailing_comma || line->fields.size() == kEntriesPerLine;
    while (line->fields.size() < n + 1 && more) {
      std::optional<DataLine> next = next_data_line();
      if (!next) break;
      line->fields.insert(line->fields.end(), next->fields.begin(), next->fields.end());
      more = next->trailing_comma || next->fields.size() == kEntriesPerLine;
    }
    const Id id = id_field(*line, 0, "element id");
    const std::string context = "element " + std::to_string(id) + " (" + type + ")";
    if (line->fields.size() != n + 1)
      throw InputError(line->where,
                       context + " needs " + std::to_string(n) + " nodes, the data line gives " +
                           std::to_string(line->fields.size() - 1) +
                           " (lines with more than 16 entries continue on the next line after a "
                           "trailing ',')");
    nodes.clear();
    for (std::size_t i = 1; i <= n; ++i) {
      const int node = node_by_id(id_field(*line, i, "node " + std::to_string(i) + " of element"),
                                  line->where, context);
      if (std::find(nodes.begin(), nodes.end(), node) != nodes.end())
        throw InputError(line->where, context + ": node " + line->fields[i] +
                                          " appears twice in the connectivity");
      nodes.push_back(node);
    }
    const int index = model_.add_element(id, type, nodes, line->where);
    if (set) set->elements.push_back(index);
  }
  if (set) sort_unique(set->elements);
}

void DeckReader::on_nset(const KeywordLine& kw) {
  const std::string name = set_name(kw, "NSET");
  const bool generate = kw.find("GENERATE") != nullptr;
  std::vector<int> members = nset(name, kw.where).nodes;
  while (std::optional<DataLine> line = next_data_line()) {
    if (generate) {
      expect_fields(*line, 2, 3, "first, last[, increment]");
      const Id first = id_field(*line, 0, "first node");
      const Id last = id_field(*line, 1, "last node");
      const Id step = line->fields.size() > 2 ? id_field(*line, 2, "increment") : 1;
      if (last < first)
        throw InputError(line->where, "GENERATE range " + std::to_string(first) + ", " +
                                          std::to_string(last) + ": last is smaller than first");
      // CalculiX lets a range pass over ids that are not nodes; they are skipped. A range that
      // names no node at all is an error.
      const std::vector<int> generated = generated_indices(
          model_.node_count(), [&](int n) { return model_.node_ids[n]; },
          [&](Id id) { return model_.node_index(id); }, first, last, step);
      members.insert(members.end(), generated.begin(), generated.end());
      if (generated.empty())
        throw InputError(line->where, "NSET=" + name + ", GENERATE: no node has an id in " +
                                          describe_range(first, last, step));
      continue;
    }
    for (std::size_t i = 0; i < line->fields.size(); ++i) {
      if (line->fields[i].empty()) continue;
      if (normalize_name(line->fields[i]) == name)
        throw InputError(line->where, "node set " + name + " cannot contain itself");
      const std::vector<int> nodes = nodes_of(*line, i, "node id or node set");
      members.insert(members.end(), nodes.begin(), nodes.end());
    }
  }
  sort_unique(members);
  model_.nsets[name].nodes = std::move(members);
}

void DeckReader::on_elset(const KeywordLine& kw) {
  const std::string name = set_name(kw, "ELSET");
  const bool generate = kw.find("GENERATE") != nullptr;
  std::vector<int> members = elset(name, kw.where).elements;
  while (std::optional<DataLine> line = next_data_line()) {
    if (generate) {
      expect_fields(*line, 2, 3, "first, last[, increment]");
      const Id first = id_field(*line, 0, "first element");
      const Id last = id_field(*line, 1, "last element");
      const Id step = line->fields.size() > 2 ? id_field(*line, 2, "increment") : 1;
      if (last < first)
        throw InputError(line->where, "GENERATE range " + std::to_string(first) + ", " +
                                          std::to_string(last) + ": last is smaller than first");
      const std::vector<int> generated = generated_indices(
          model_.element_count(), [&](int e) { return model_.elements[e].id; },
          [&](Id id) { return model_.element_index(id); }, first, last, step);
      members.insert(members.end(), generated.begin(), generated.end());
      if (generated.empty())
        throw InputError(line->where, "ELSET=" + name + ", GENERATE: no element has an id in " +
                                          describe_range(first, last, step));
      continue;
    }
    for (std::size_t i = 0; i < line->fields.size(); ++i) {
      if (line->fields[i].empty()) continue;
      if (normalize_name(line->fields[i]) == name)
        throw InputError(line->where, "element set " + name + " cannot contain itself");
      const std::vector<int> elements = elements_of(*line, i, "element id or element set");
      members.insert(members.end(), elements.begin(), elements.end());
    }
  }
  sort_unique(members);
  model_.elsets[name].elements = std::move(members);
}

}  // namespace styk::inp
