#include "results_rows.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "h5_util.hpp"
#include "results_schema.hpp"

namespace styk::io {
namespace {

enum class RowsOf {
  Node,
  Element,
  ElementNode,
  IntegrationPoint,
  Station,  // beam section forces and moments: per element by station_offsets
  ContactNode,
  ContactPair,
  Balance,
  Unknown
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The index arrays a row is named from, read as needed (small next to the fields themselves).
class IdLookup {
 public:
  IdLookup(hid_t file, std::string increment) : file_(file), increment_(std::move(increment)) {}

  std::uint64_t nodes() { return ints("/model/nodes/ids").size(); }
  std::uint64_t elements() { return ints("/model/elements/ids").size(); }
  std::uint64_t element_nodes() { return ints("/model/elements/connectivity").size(); }
  std::uint64_t points() {
    const auto& offsets = ints(increment_ + "/ip_offsets");
    return offsets.empty() ? 0 : static_cast<std::uint64_t>(offsets.back());
  }
  std::string node(std::uint64_t index) { return "node " + id("/model/nodes/ids", index); }
  std::string element(std::uint64_t index) { return "element " + id("/model/elements/ids", index); }
  // Row `row` of a layout split per element by `offsets` (connectivity or integration points).
  std::string element_part(const std::string& offsets_path, const char* part, std::uint64_t row) {
    const auto& offsets = ints(offsets_path);
    const auto it =
        std::upper_bound(offsets.begin(), offsets.end(), static_cast<std::int64_t>(row));
    if (it == offsets.begin() || it == offsets.end()) return "row " + std::to_string(row);
    const auto e = static_cast<std::uint64_t>(it - offsets.begin() - 1);
    return element(e) + ", " + part + " " + std::to_string(row - offsets[e] + 1);
  }
  std::string contact_node(const std::string& contact_group, std::uint64_t row) {
    const auto& nodes = ints(contact_group + "/nodes");
    if (row >= nodes.size() || nodes[row] < 0) return "contact row " + std::to_string(row);
    return "contact slave " + node(static_cast<std::uint64_t>(nodes[row]));
  }

 private:
  const std::vector<std::int64_t>& ints(const std::string& path) {
    if (path != cached_path_) {
      cached_path_ = path;
      cached_.clear();
      try {
        h5::read_int64(file_, path, cached_);
      } catch (const std::exception&) {
        cached_.clear();  // damaged or absent: the caller falls back to row numbers
      }
    }
    return cached_;
  }
  std::string id(const std::string& path, std::uint64_t index) {
    const auto& ids = ints(path);
    return index < ids.size() ? std::to_string(ids[index]) : "#" + std::to_string(index + 1);
  }

  hid_t file_;
  std::string increment_;
  std::string cached_path_;
  std::vector<std::int64_t> cached_;
};

// What the rows of a dataset are, from where it sits and its name; a dataset this build does not
// know (a newer field) is matched by its row count when exactly one entity count fits.
RowsOf rows_of(const std::string& group, const std::string& name, std::uint64_t rows,
               IdLookup& ids) {
  if (group == "/model/nodes") return RowsOf::Node;
  if (group == "/model/elements")
    return name == "connectivity" ? RowsOf::ElementNode : RowsOf::Element;
  if (group.rfind("/model/", 0) == 0) return RowsOf::Unknown;  // sets: members, named by row
  if (ends_with(group, "/contact")) {
    if (name == "pair_force" || name == "pair_moment") return RowsOf::ContactPair;
    return name == "equilibrium" ? RowsOf::Balance : RowsOf::ContactNode;
  }
  if (name == "U" || name == "RF" || name == "UR" || name == "RM" || name == "value" ||
      name == "reaction" || name == "flux_nodal")
    return RowsOf::Node;
  if (name == "SF" || name == "SM" || name == "SFQ") return RowsOf::Station;
  if (name == "S" || name == "E" || name == "gradient" || name == "flux")
    return RowsOf::IntegrationPoint;
  for (const schema::RecoveredField& field : schema::kRecoveredFields)
    if (name == field.name)
      return field.per == schema::FieldPer::Node      ? RowsOf::Node
             : field.per == schema::FieldPer::Element ? RowsOf::Element
                                                      : RowsOf::ElementNode;
  std::vector<RowsOf> fits;
  if (rows == ids.nodes()) fits.push_back(RowsOf::Node);
  if (rows == ids.elements()) fits.push_back(RowsOf::Element);
  if (rows == ids.element_nodes()) fits.push_back(RowsOf::ElementNode);
  if (rows == ids.points()) fits.push_back(RowsOf::IntegrationPoint);
  return fits.size() == 1 ? fits.front() : RowsOf::Unknown;
}

std::string format_value(double v) { return std::isnan(v) ? "NaN" : v > 0 ? "+Inf" : "-Inf"; }

std::string row_name(hid_t file, const std::string& dataset_path, std::uint64_t rows,
                     std::uint64_t row) {
  const std::size_t slash = dataset_path.rfind('/');
  const std::string group = slash == std::string::npos ? "" : dataset_path.substr(0, slash);
  const std::string name = dataset_path.substr(slash + 1);
  // Datasets of a contact or scalar subgroup belong to the increment above it.
  const std::string increment = ends_with(group, "/contact") || ends_with(group, "/scalar")
                                    ? group.substr(0, group.rfind('/'))
                                    : group;
  const h5::QuietErrors quiet;
  IdLookup ids(file, increment);
  switch (rows_of(group, name, rows, ids)) {
    case RowsOf::Node:
      return ids.node(row);
    case RowsOf::Element:
      return ids.element(row);
    case RowsOf::ElementNode:
      return ids.element_part("/model/elements/offsets", "its node", row);
    case RowsOf::IntegrationPoint:
      return ids.element_part(increment + "/ip_offsets", "integration point", row);
    case RowsOf::Station:
      return ids.element_part(increment + "/station_offsets", "station", row);
    case RowsOf::ContactNode:
      return ids.contact_node(group, row);
    case RowsOf::ContactPair:
      return "contact pair " + std::to_string(row + 1);
    case RowsOf::Balance: {
      static const char* const kRows[] = {"applied loads", "reactions", "contact on slaves",
                                          "contact on masters"};
      return row < 4 ? std::string("the sum of ") + kRows[row] : "row " + std::to_string(row);
    }
    case RowsOf::Unknown:
      break;
  }
  return "row " + std::to_string(row);
}

}  // namespace

std::string describe_row(hid_t file, const std::string& dataset_path, std::uint64_t row) {
  std::uint64_t rows = 0;
  const h5::QuietErrors quiet;
  const hid_t dataset = H5Dopen2(file, dataset_path.c_str(), H5P_DEFAULT);
  if (dataset >= 0) {
    const hid_t space = H5Dget_space(dataset);
    hsize_t dims[2] = {0, 0};
    if (space >= 0 && H5Sget_simple_extent_ndims(space) >= 1)
      H5Sget_simple_extent_dims(space, dims, nullptr);
    if (space >= 0) H5Sclose(space);
    H5Dclose(dataset);
    rows = dims[0];
  }
  H5Eclear2(H5E_DEFAULT);
  return row_name(file, dataset_path, rows, row);
}

std::string describe_non_finite(hid_t file, const h5::NonFiniteError& error) {
  const std::string& object = error.object();
  const h5::NonFiniteValue& first = error.first();
  const std::size_t at = object.find('@');
  if (at != std::string::npos)
    return "attribute " + object.substr(at + 1) + " of " + object.substr(0, at) + " is " +
           format_value(first.value) + ", not a finite number";
  std::string text = "dataset " + object + ": " + row_name(file, object, first.rows, first.row);
  if (first.cols > 1) text += ", component " + std::to_string(first.column + 1);
  text += " is " + format_value(first.value);
  if (first.count > 1)
    text += " (" + std::to_string(first.count) + " values of the dataset are not finite numbers)";
  else
    text += ", not a finite number";
  return text;
}

}  // namespace styk::io
