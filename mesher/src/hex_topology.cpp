#include "styk/mesher/hex_topology.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

namespace styk::mesher {
namespace {

const std::vector<Vec3> kCorners = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
const std::vector<Vec3> kMidEdges = {{0, -1, -1}, {1, 0, -1}, {0, 1, -1}, {-1, 0, -1},
                                     {0, -1, 1},  {1, 0, 1},  {0, 1, 1},  {-1, 0, 1},
                                     {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0}};

std::vector<Vec3> concat(std::vector<Vec3> a, const std::vector<Vec3>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::map<std::string, std::vector<Vec3>> make_layouts() {
  std::map<std::string, std::vector<Vec3>> layouts;
  layouts["C3D8"] = kCorners;
  layouts["C3D8R"] = kCorners;
  layouts["C3D8I"] = kCorners;
  layouts["C3D20"] = concat(kCorners, kMidEdges);
  return layouts;
}

}  // namespace

const std::vector<Vec3>& natural_nodes(const std::string& type) {
  static const std::map<std::string, std::vector<Vec3>> layouts = make_layouts();
  const auto it = layouts.find(type);
  if (it == layouts.end()) throw std::invalid_argument("mesher: unknown element type " + type);
  return it->second;
}

FaceAxis face_axis(int face) {
  static constexpr FaceAxis kFaces[6] = {{2, -1}, {2, 1}, {1, -1}, {0, 1}, {1, 1}, {0, -1}};
  if (face < 0 || face > 5) throw std::invalid_argument("mesher: face index out of range");
  return kFaces[face];
}

int face_index(int axis, int value) {
  for (int f = 0; f < 6; ++f)
    if (face_axis(f).axis == axis && face_axis(f).value == value) return f;
  throw std::invalid_argument("mesher: bad face axis");
}

std::vector<int> face_local_nodes(const std::string& type, int face) {
  const FaceAxis fa = face_axis(face);
  const std::vector<Vec3>& nat = natural_nodes(type);
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(nat.size()); ++i)
    if (std::abs(nat[i][fa.axis] - fa.value) < 1e-12) out.push_back(i);
  return out;
}

std::vector<int> face_corner_nodes(int face) { return face_local_nodes("C3D8", face); }

void hex8_shape(const Vec3& xi, double N[8]) {
  for (int i = 0; i < 8; ++i)
    N[i] = 0.125 * (1 + kCorners[i][0] * xi[0]) * (1 + kCorners[i][1] * xi[1]) *
           (1 + kCorners[i][2] * xi[2]);
}

void hex20_shape(const Vec3& xi, double N[20]) {
  for (int i = 0; i < 8; ++i) {
    const Vec3& c = kCorners[i];
    N[i] = 0.125 * (1 + c[0] * xi[0]) * (1 + c[1] * xi[1]) * (1 + c[2] * xi[2]) *
           (c[0] * xi[0] + c[1] * xi[1] + c[2] * xi[2] - 2);
  }
  for (int m = 0; m < 12; ++m) {
    const Vec3& c = kMidEdges[m];
    double v = 0.25;
    for (int d = 0; d < 3; ++d) v *= c[d] == 0 ? (1 - xi[d] * xi[d]) : (1 + c[d] * xi[d]);
    N[8 + m] = v;
  }
}

Vec3 rotate(const CubeRotation& R, const Vec3& xi) {
  Vec3 out{0, 0, 0};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[r] += R[r][c] * xi[c];
  return out;
}

}  // namespace styk::mesher
