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
  const double a = 1.0 / std::sqrt(5.0);
  std::map<std::string, std::vector<Vec3>> layouts;
  layouts["C3D8"] = kCorners;
  layouts["C3D8R"] = kCorners;
  layouts["C3D8I"] = kCorners;
  layouts["C3D20"] = concat(kCorners, kMidEdges);
  layouts["C3D20R"] = layouts["C3D20"];
  // Face centres in face order S1..S6, then the element centre.
  layouts["C3D27"] =
      concat(layouts["C3D20"],
             {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 0}});
  // elements-ref section 1: face centres 9 S1, 10 S2, 11 S3, 12 S5, 13 S6, 14 S4.
  layouts["C3D14"] =
      concat(kCorners, {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}});
  layouts["C3D21"] = concat(layouts["C3D20"], {{0, 0, -1}});
  layouts["C3D28"] =
      concat(kCorners, {{-1, -1, 0},  {1, -1, 0},   {1, 1, 0},   {-1, 1, 0},   {0, -1, 1},
                        {1, 0, 1},    {0, 1, 1},    {-1, 0, 1},  {-a, -1, -1}, {a, -1, -1},
                        {1, -a, -1},  {1, a, -1},   {a, 1, -1},  {-a, 1, -1},  {-1, a, -1},
                        {-1, -a, -1}, {-a, -a, -1}, {a, -a, -1}, {a, a, -1},   {-a, a, -1}});
  return layouts;
}

int sign_of(double v) { return v > 0.5 ? 1 : (v < -0.5 ? -1 : 0); }

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

Vec3 map_point(const std::string& type, const std::vector<Vec3>& element_coords, const Vec3& xi) {
  double N[20];
  int n = 0;
  if (type == "C3D8") {
    hex8_shape(xi, N);
    n = 8;
  } else if (type == "C3D20" || type == "C3D20R") {
    hex20_shape(xi, N);
    n = 20;
  } else {
    throw std::invalid_argument("mesher: map_point needs a C3D8 or C3D20 element, not " + type);
  }
  Vec3 x{0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) x[d] += N[i] * element_coords[i][d];
  return x;
}

Vec3 rotate(const CubeRotation& R, const Vec3& xi) {
  Vec3 out{0, 0, 0};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[r] += R[r][c] * xi[c];
  return out;
}

CubeRotation rotation_to_bottom(int face) {
  const FaceAxis target = face_axis(face);
  // Enumerate the 24 proper rotations (signed permutations with det +1) and take the first that
  // carries the new bottom centre (0, 0, -1) onto the old face centre.
  static constexpr int kPerms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                       {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  static constexpr int kParity[6] = {1, -1, -1, 1, 1, -1};
  for (int p = 0; p < 6; ++p)
    for (int s = 0; s < 8; ++s) {
      const int sx = (s & 1) ? -1 : 1, sy = (s & 2) ? -1 : 1, sz = (s & 4) ? -1 : 1;
      if (kParity[p] * sx * sy * sz != 1) continue;
      CubeRotation R{};
      const int signs[3] = {sx, sy, sz};
      for (int r = 0; r < 3; ++r) R[r][kPerms[p][r]] = signs[r];
      const Vec3 c = rotate(R, {0, 0, -1});
      if (sign_of(c[target.axis]) == target.value) return R;
    }
  throw std::logic_error("mesher: no cube rotation found");
}

std::vector<int> rotated_numbering(const std::string& type, const CubeRotation& R) {
  const std::vector<Vec3>& nat = natural_nodes(type);
  std::vector<int> perm(nat.size(), -1);
  for (std::size_t k = 0; k < nat.size(); ++k) {
    const Vec3 old = rotate(R, nat[k]);
    for (std::size_t i = 0; i < nat.size(); ++i)
      if (std::abs(nat[i][0] - old[0]) + std::abs(nat[i][1] - old[1]) +
              std::abs(nat[i][2] - old[2]) <
          1e-9)
        perm[k] = static_cast<int>(i);
    if (perm[k] < 0)
      throw std::invalid_argument("mesher: " + type + " cannot be re-oriented that way");
  }
  return perm;
}

int rotated_face(const CubeRotation& R, int old_face) {
  // New face g lies where R maps its centre onto the centre of the old face.
  const FaceAxis oa = face_axis(old_face);
  for (int g = 0; g < 6; ++g) {
    const FaceAxis ga = face_axis(g);
    Vec3 centre{0, 0, 0};
    centre[ga.axis] = ga.value;
    const Vec3 old = rotate(R, centre);
    if (sign_of(old[oa.axis]) == oa.value) return g;
  }
  throw std::logic_error("mesher: rotated face not found");
}

}  // namespace styk::mesher
