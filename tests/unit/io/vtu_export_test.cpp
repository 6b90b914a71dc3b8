// VTU export: the file is parsed back with a small XML scanner and base64 decoder written here
// (VTK itself is not a dependency) and every array is checked against the model and results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>

#include "io_test_support.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/io/vtu_export.hpp"
#include "support/element_registries.hpp"

namespace styk {
namespace {

std::vector<unsigned char> base64_decode(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=' || std::isspace(static_cast<unsigned char>(c))) continue;
    const int v = value(c);
    if (v < 0) throw std::runtime_error(std::string("bad base64 character ") + c);
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  return out;
}

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
};

// Splits the document into elements, checking that every opened tag is closed in order. Returns
// the elements in document order (each with the text directly inside it).
std::vector<XmlElement> scan_xml(const std::string& doc) {
  std::vector<XmlElement> elements;
  std::vector<std::size_t> open;
  std::size_t pos = 0;
  while ((pos = doc.find('<', pos)) != std::string::npos) {
    const std::size_t end = doc.find('>', pos);
    if (end == std::string::npos) throw std::runtime_error("unterminated tag");
    std::string tag = doc.substr(pos + 1, end - pos - 1);
    const std::size_t after = end + 1;
    pos = after;
    if (tag[0] == '?' || tag[0] == '!') continue;
    if (tag[0] == '/') {
      if (open.empty() || elements[open.back()].name != tag.substr(1))
        throw std::runtime_error("mismatched closing tag " + tag);
      open.pop_back();
      continue;
    }
    const bool self_closing = tag.back() == '/';
    if (self_closing) tag.pop_back();
    XmlElement element;
    std::size_t p = tag.find(' ');
    element.name = tag.substr(0, p);
    while (p != std::string::npos && (p = tag.find_first_not_of(' ', p)) != std::string::npos) {
      const std::size_t eq = tag.find("=\"", p);
      const std::size_t close = tag.find('"', eq + 2);
      if (eq == std::string::npos || close == std::string::npos)
        throw std::runtime_error("bad attribute in " + tag);
      element.attributes[tag.substr(p, eq - p)] = tag.substr(eq + 2, close - eq - 2);
      p = close + 1;
    }
    const std::size_t next = doc.find('<', after);
    element.text = doc.substr(after, next - after);
    elements.push_back(element);
    if (!self_closing) open.push_back(elements.size() - 1);
  }
  if (!open.empty()) throw std::runtime_error("unclosed tag " + elements[open.back()].name);
  return elements;
}

template <typename T>
std::vector<T> decode_array(const XmlElement& array) {
  const std::vector<unsigned char> bytes = base64_decode(array.text);
  std::uint64_t size = 0;
  if (bytes.size() < sizeof size) throw std::runtime_error("array shorter than its header");
  std::memcpy(&size, bytes.data(), sizeof size);
  if (bytes.size() != sizeof size + size) throw std::runtime_error("header does not match data");
  std::vector<T> values(size / sizeof(T));
  if (size > 0) std::memcpy(values.data(), bytes.data() + sizeof size, size);
  return values;
}

const XmlElement& data_array(const std::vector<XmlElement>& doc, const std::string& name) {
  for (const XmlElement& e : doc)
    if (e.name == "DataArray" && e.attributes.count("Name") && e.attributes.at("Name") == name)
      return e;
  throw std::runtime_error("no DataArray " + name);
}

bool has_array(const std::vector<XmlElement>& doc, const std::string& name) {
  try {
    data_array(doc, name);
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

// A 3-node bar registered by the test, as a plug-in would: its middle node is numbered second
// (Abaqus), so its VTK cell (a quadratic edge, middle node last) reorders the nodes.
class Bar3 : public TElement {
 public:
  std::string name() const override { return "BAR3"; }
  std::string description() const override { return "test bar"; }
  int node_count() const override { return 3; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {}
  IntegrationRule rule(RuleKind) const override { return {}; }
  int face_rule_order() const override { return 1; }
  VtkCell vtk_cell() const override { return {vtk::kQuadraticEdge, {0, 2, 1}}; }

 private:
  std::vector<Vec3> nodes_{{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  std::vector<FaceDef> faces_;
};

// A 5-node solid that describes no VTK cell (its corners make no cell the default knows).
class Pyramid5 : public TElement {
 public:
  std::string name() const override { return "PYR5"; }
  std::string description() const override { return "test pyramid"; }
  int node_count() const override { return 5; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {}
  IntegrationRule rule(RuleKind) const override { return {}; }
  int face_rule_order() const override { return 1; }

 private:
  std::vector<Vec3> nodes_{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
  std::vector<FaceDef> faces_{FaceDef{{0, 1, 2, 3}}};
};

const ElementRegistry& test_registry() {
  static const ElementRegistry registry = [] {
    ElementRegistry r = test::builtin_registry();
    r.add(std::make_unique<Bar3>(), "test plug-in");
    r.add(std::make_unique<Pyramid5>(), "test plug-in");
    return r;
  }();
  return registry;
}

// Two C3D8 (plain and reduced) sharing a face, nodes on a 3 x 2 x 2 grid, and a plug-in's 3-node
// bar.
Model two_hex_model() {
  Model model;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        model.add_node(100 + model.node_count(), {1.0 * i, 1.0 * j, 1.0 * k}, {});
  model.add_element(1, "C3D8", {0, 1, 4, 3, 6, 7, 10, 9}, {});
  model.add_element(3, "C3D8R", {1, 2, 5, 4, 7, 8, 11, 10}, {});
  model.add_element(4, "BAR3", {0, 1, 2}, {});
  return model;
}

IncrementResult two_hex_results(const Model& model) {
  IncrementResult inc;
  inc.total_time = 2.5;
  for (int n = 0; n < model.node_count(); ++n) {
    inc.U.push_back({1.0 * n, 2.0 * n, 3.0 * n});
    inc.RF.push_back({0.0, -1.0 * n, 0.0});
  }
  inc.ip_offset = {0, 8, 10, 11};
  for (int p = 0; p < 8; ++p) inc.S.push_back({1.0 * p, 0, 0, 0, 0, 0});
  inc.S.push_back({10, 0, 0, 1, 2, 3});
  inc.S.push_back({20, 0, 0, 1, 2, 3});
  inc.S.push_back({5, 5, 5, 0, 0, 0});
  return inc;
}

// The built-in types describe their cells themselves (TElement::vtk_cell()).
TEST(VtuExport, BuiltInTypesDescribeTheirCells) {
  const ElementRegistry& r = test_registry();
  const std::map<std::string, int> expected = {{"C3D8", vtk::kHexahedron},
                                               {"C3D8I", vtk::kHexahedron},
                                               {"C3D8R", vtk::kHexahedron},
                                               {"C3D20", vtk::kQuadraticHexahedron},
                                               {"C3D20R", vtk::kQuadraticHexahedron},
                                               {"C3D27", vtk::kQuadraticHexahedron},
                                               {"CPS4", vtk::kQuad},
                                               {"CPE8", vtk::kQuadraticQuad},
                                               {"T3D2", vtk::kLine}};
  for (const auto& [type, cell] : expected) {
    EXPECT_EQ(r.find(type)->vtk_cell().type, cell) << type;
  }
  // Every registered type has a cell.
  for (const std::string& type : r.names()) {
    if (type != "PYR5") {
      EXPECT_GT(r.find(type)->vtk_cell().type, 0) << type;
    }
  }
}

// A type nobody registered is not skipped: the export stops at the element's line, names the
// type, and writes no file.
TEST(VtuExport, UnknownTypeIsRefusedByNameAndNothingIsWritten) {
  Model model = two_hex_model();
  model.add_element(7, "C3D99", {0, 1, 2}, {"deck.inp", 42});
  const std::string path = io_test::fresh_dir("vtu_unknown") + "/unknown.vtu";
  try {
    write_vtu(path, model, test_registry(), nullptr);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:42"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("element 7 has type C3D99"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(io_test::file_exists(path));
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));
}

TEST(VtuExport, TypeWithoutACellIsRefusedByName) {
  Model model = two_hex_model();
  model.add_element(8, "PYR5", {0, 1, 4, 3, 7}, {"deck.inp", 43});
  const std::string path = io_test::fresh_dir("vtu_nocell") + "/nocell.vtu";
  try {
    write_vtu(path, model, test_registry(), nullptr);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 8 (PYR5) describes no VTK cell"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(io_test::file_exists(path));
}

TEST(VtuExport, WritesMeshAndIncrementThatParseBack) {
  const Model model = two_hex_model();
  const IncrementResult inc = two_hex_results(model);
  const std::string path = io_test::fresh_dir("vtu") + "/two.vtu";
  const VtuExportSummary summary = write_vtu(path, model, test_registry(), &inc);
  EXPECT_EQ(summary.cells_written, 3);
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));

  const std::vector<XmlElement> doc = scan_xml(io_test::read_text(path));
  ASSERT_FALSE(doc.empty());
  EXPECT_EQ(doc[0].name, "VTKFile");
  EXPECT_EQ(doc[0].attributes.at("type"), "UnstructuredGrid");
  EXPECT_EQ(doc[0].attributes.at("header_type"), "UInt64");
  const auto piece =
      std::find_if(doc.begin(), doc.end(), [](const XmlElement& e) { return e.name == "Piece"; });
  ASSERT_NE(piece, doc.end());
  EXPECT_EQ(piece->attributes.at("NumberOfPoints"), "12");
  EXPECT_EQ(piece->attributes.at("NumberOfCells"), "3");

  EXPECT_EQ(decode_array<std::uint8_t>(data_array(doc, "types")),
            (std::vector<std::uint8_t>{12, 12, 21}));
  EXPECT_EQ(decode_array<std::int64_t>(data_array(doc, "offsets")),
            (std::vector<std::int64_t>{8, 16, 19}));
  EXPECT_EQ(decode_array<std::int64_t>(data_array(doc, "connectivity")),
            (std::vector<std::int64_t>{0, 1, 4, 3, 6, 7, 10, 9,   // C3D8
                                       1, 2, 5, 4, 7, 8, 11, 10,  // C3D8R
                                       0, 2, 1}));                // BAR3, middle node last
  EXPECT_EQ(decode_array<std::int64_t>(data_array(doc, "element_id")),
            (std::vector<std::int64_t>{1, 3, 4}));
  const std::vector<double> points = decode_array<double>(data_array(doc, "Points"));
  ASSERT_EQ(points.size(), 36u);
  EXPECT_EQ(points[3 * 11 + 0], 2.0);
  EXPECT_EQ(points[3 * 11 + 2], 1.0);
  const std::vector<double> u = decode_array<double>(data_array(doc, "U"));
  ASSERT_EQ(u.size(), 36u);
  EXPECT_EQ(u[3 * 7 + 2], 21.0);
  EXPECT_EQ(data_array(doc, "U").attributes.at("NumberOfComponents"), "3");
  EXPECT_EQ(decode_array<double>(data_array(doc, "RF"))[3 * 5 + 1], -5.0);
  EXPECT_EQ(decode_array<double>(data_array(doc, "TimeValue")), std::vector<double>{2.5});

  // Means over the integration points, in VTK's XX YY ZZ XY YZ XZ order:
  // element 1: S11 = mean(0..7) = 3.5; element 3: (15, 0, 0, 1, 3, 2); element 4: (5, 5, 5, 0...).
  EXPECT_EQ(decode_array<double>(data_array(doc, "S_ip_mean")),
            (std::vector<double>{3.5, 0, 0, 0, 0, 0, 15, 0, 0, 1, 3, 2, 5, 5, 5, 0, 0, 0}));
  // Mises: uniaxial 3.5; sqrt(0.5 (15^2 + 15^2) + 3 (1 + 4 + 9)) = sqrt(267); hydrostatic 0.
  const std::vector<double> mises = decode_array<double>(data_array(doc, "S_ip_mean_mises"));
  ASSERT_EQ(mises.size(), 3u);
  EXPECT_NEAR(mises[0], 3.5, 1e-12);
  EXPECT_NEAR(mises[1], std::sqrt(267.0), 1e-12);
  EXPECT_NEAR(mises[2], 0.0, 1e-12);
  // No nodal stresses and no contact in this increment: no such arrays.
  EXPECT_FALSE(has_array(doc, "S_nodal_II"));
  EXPECT_FALSE(has_array(doc, "CSTATUS"));
}

// Nodal stresses (both averaging methods) go out as 6-component point data in VTK order with
// their Mises values; contact output as one number per node, NaN away from the slave nodes.
TEST(VtuExport, WritesNodalStressesAndContactPointData) {
  const Model model = two_hex_model();
  IncrementResult inc = two_hex_results(model);
  for (int n = 0; n < model.node_count(); ++n) {
    inc.S_nodal_I.push_back({1.0 * n, 0, 0, 0, 0, 0});
    inc.S_nodal_II.push_back({0, 0, 0, 1.0 * n, 2.0 * n, 3.0 * n});  // 12, 13, 23
  }
  ContactNodeResult a;  // node 6: sticking, pressure 4, shear (3, 4) -> 5, slip (0.6, 0.8) -> 1
  a.node = 6, a.status = ContactStatus::Stick, a.pressure = 4.0, a.shear = {3.0, 4.0};
  a.slip = {0.6, 0.8}, a.gap = 0.0;
  ContactNodeResult b;  // node 7: open with a gap of 0.25
  b.node = 7, b.status = ContactStatus::Open, b.gap = 0.25;
  ContactNodeResult c;  // node 7 again in a second pair, slipping: the most engaged entry wins
  c.pair = 1, c.node = 7, c.status = ContactStatus::Slip, c.pressure = 2.0, c.slip = {0.0, -2.0};
  inc.contact = {a, b, c};

  const std::string path = io_test::fresh_dir("vtu_nodal") + "/nodal.vtu";
  write_vtu(path, model, test_registry(), &inc);
  const std::vector<XmlElement> doc = scan_xml(io_test::read_text(path));

  const std::vector<double> s1 = decode_array<double>(data_array(doc, "S_nodal_I"));
  ASSERT_EQ(s1.size(), 6u * 12u);
  EXPECT_EQ(data_array(doc, "S_nodal_I").attributes.at("NumberOfComponents"), "6");
  EXPECT_EQ(data_array(doc, "S_nodal_II").attributes.at("ComponentName4"), "YZ");
  EXPECT_EQ(s1[6 * 5 + 0], 5.0);
  const std::vector<double> s2 = decode_array<double>(data_array(doc, "S_nodal_II"));
  ASSERT_EQ(s2.size(), 6u * 12u);
  // Node 2: (12, 13, 23) = (2, 4, 6) -> VTK XY YZ XZ = 2, 6, 4.
  EXPECT_EQ((std::vector<double>(s2.begin() + 12, s2.begin() + 18)),
            (std::vector<double>{0, 0, 0, 2, 6, 4}));
  const std::vector<double> m1 = decode_array<double>(data_array(doc, "S_nodal_I_mises"));
  const std::vector<double> m2 = decode_array<double>(data_array(doc, "S_nodal_II_mises"));
  ASSERT_EQ(m1.size(), 12u);
  ASSERT_EQ(m2.size(), 12u);
  EXPECT_NEAR(m1[5], 5.0, 1e-12);  // uniaxial
  // Pure shear (2, 4, 6): sqrt(3 (4 + 16 + 36)) = sqrt(168).
  EXPECT_NEAR(m2[2], std::sqrt(168.0), 1e-12);

  const std::vector<double> pressure = decode_array<double>(data_array(doc, "CPRESS"));
  const std::vector<double> slip = decode_array<double>(data_array(doc, "CSLIP"));
  const std::vector<double> status = decode_array<double>(data_array(doc, "CSTATUS"));
  const std::vector<double> shear = decode_array<double>(data_array(doc, "CSHEAR"));
  const std::vector<double> gap = decode_array<double>(data_array(doc, "CGAP"));
  for (const auto* v : {&pressure, &slip, &status, &shear, &gap}) {
    ASSERT_EQ(v->size(), 12u);
    for (int n = 0; n < 12; ++n) {
      if (n != 6 && n != 7) {
        EXPECT_TRUE(std::isnan((*v)[n])) << "node " << n;
      }
    }
  }
  EXPECT_EQ(pressure[6], 4.0);
  EXPECT_NEAR(shear[6], 5.0, 1e-12);
  EXPECT_NEAR(slip[6], 1.0, 1e-12);
  EXPECT_EQ(status[6], 1.0);
  EXPECT_EQ(gap[6], 0.0);
  EXPECT_EQ(status[7], 2.0);  // the slipping entry, not the open one
  EXPECT_EQ(pressure[7], 2.0);
  EXPECT_NEAR(slip[7], 2.0, 1e-12);
}

TEST(VtuExport, MeshOnlyHasNoResultArrays) {
  const std::string path = io_test::fresh_dir("vtu_mesh") + "/mesh.vtu";
  const VtuExportSummary summary = write_vtu(path, two_hex_model(), test_registry(), nullptr);
  EXPECT_EQ(summary.cells_written, 3);
  const std::vector<XmlElement> doc = scan_xml(io_test::read_text(path));
  EXPECT_FALSE(has_array(doc, "U"));
  EXPECT_FALSE(has_array(doc, "S_ip_mean"));
  EXPECT_FALSE(has_array(doc, "S_nodal_I"));
  EXPECT_FALSE(has_array(doc, "CPRESS"));
  EXPECT_TRUE(has_array(doc, "element_id"));
  EXPECT_EQ(decode_array<double>(data_array(doc, "Points")).size(), 36u);
}

TEST(VtuExport, MismatchedResultsThrowAndWriteNothing) {
  const Model model = two_hex_model();
  IncrementResult inc = two_hex_results(model);
  inc.U.resize(5);
  const std::string path = io_test::fresh_dir("vtu_bad") + "/bad.vtu";
  EXPECT_THROW(write_vtu(path, model, test_registry(), &inc), std::runtime_error);
  EXPECT_FALSE(io_test::file_exists(path));
  EXPECT_FALSE(io_test::file_exists(path + ".tmp"));
}

}  // namespace
}  // namespace styk
