#include "c3d14.hpp"

#include <array>

#include "styk/elements/hex_shapes.hpp"

namespace styk::plugins {

namespace {

// The six face-centre nodes 9-14 (0-based 8-13): the face each one sits on, as the natural axis
// (0/1/2 = xi/eta/zeta) and side (-1/+1), and its 0-based Abaqus face index (S1 = 0).
struct FaceCentre {
  int axis;
  int side;
  int face;
};
constexpr std::array<FaceCentre, 6> kCentres = {{
    {2, -1, 0},  // node 9:  zeta = -1, S1
    {2, +1, 1},  // node 10: zeta = +1, S2
    {1, -1, 2},  // node 11: eta = -1,  S3
    {1, +1, 4},  // node 12: eta = +1,  S5
    {0, -1, 5},  // node 13: xi = -1,   S6
    {0, +1, 3},  // node 14: xi = +1,   S4
}};

// Local index (0-based) of the centre node of Abaqus face f.
int centre_node_of_face(int face) {
  for (int k = 0; k < 6; ++k)
    if (kCentres[k].face == face) return 8 + k;
  return -1;
}

std::vector<Vec3> c3d14_nodes() {
  std::vector<Vec3> nodes = hex8_natural_nodes();
  for (const FaceCentre& c : kCentres) {
    Vec3 x{0.0, 0.0, 0.0};
    x[c.axis] = c.side;
    nodes.push_back(x);
  }
  return nodes;
}

std::vector<FaceDef> c3d14_faces() {
  std::vector<FaceDef> faces = hex_faces(false);  // Abaqus corner lists
  for (int f = 0; f < 6; ++f) faces[f].nodes.push_back(centre_node_of_face(f));
  return faces;
}

}  // namespace

C3D14::C3D14() : nodes_(c3d14_nodes()), faces_(c3d14_faces()) {}

std::string C3D14::description() const {
  return "14-node contact hexahedron (corners + face centres, positive nodal areas on every "
         "face), 3x3x3 Gauss";
}

// Compact form of the corrected thesis set (elements-ref section 2, verified identical):
// face bubble B_f = 1/2 (1 + s x_a) prod_{b != a} (1 - x_b^2) for the face x_a = s, and corner
// N_c = trilinear_c - 1/4 (sum of the bubbles of the three faces through c).
void C3D14::der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
                Eigen::Ref<Eigen::MatrixXd> dN) const {
  hex8_shape(xi, N.head<8>(), dN.topRows<8>());
  std::array<double, 6> bubble{};
  std::array<Eigen::RowVector3d, 6> bubble_grad{};
  for (int k = 0; k < 6; ++k) {
    const FaceCentre& c = kCentres[k];
    const int p = (c.axis + 1) % 3, q = (c.axis + 2) % 3;
    const double normal = 0.5 * (1.0 + c.side * xi[c.axis]);
    const double bp = 1.0 - xi[p] * xi[p], bq = 1.0 - xi[q] * xi[q];
    bubble[k] = normal * bp * bq;
    bubble_grad[k](c.axis) = 0.5 * c.side * bp * bq;
    bubble_grad[k](p) = -2.0 * xi[p] * normal * bq;
    bubble_grad[k](q) = -2.0 * xi[q] * normal * bp;
    N(8 + k) = bubble[k];
    dN.row(8 + k) = bubble_grad[k];
  }
  for (int i = 0; i < 8; ++i) {
    const Vec3& corner = nodes_[i];
    for (int k = 0; k < 6; ++k)
      if (corner[kCentres[k].axis] == kCentres[k].side) {  // face k passes through corner i
        N(i) -= 0.25 * bubble[k];
        dN.row(i) -= 0.25 * bubble_grad[k];
      }
  }
}

IntegrationRule C3D14::rule(RuleKind kind) const {
  return kind == RuleKind::Reduced ? gauss_rule(2, 2, 2) : gauss_rule(3, 3, 3);
}

}  // namespace styk::plugins
