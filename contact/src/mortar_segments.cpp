#include "mortar_segments.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "styk/core/face_param.hpp"

namespace styk::contact {
namespace {

using Polygon = std::vector<Eigen::Vector2d>;

// Gauss points per direction (6, the most face_rule has): the collapsed triangle rule on the
// overlap's triangles is exact to total degree 10, the degree of a bicubic C3D28 dual function
// times a biquadratic master function on flat faces; over a whole slave face 6 x 6 points
// integrate products of bicubics.
constexpr int kOverlapOrder = 6;
constexpr int kFaceOrder = 6;
// A boundary edge that does not project onto a straight line is replaced by this many chords.
constexpr int kCurvedEdgeChords = 16;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a[0] * b[1] - a[1] * b[0];
}

bool is_triangle(const PlacedFace& f) {
  const FaceDef& face = f.element->faces()[f.face];
  return face.axis < 0 && FaceParam(*f.element, face).triangle();
}

// The corners of the face's (p, q) domain (face_param.hpp), counter-clockwise, and its centre.
Polygon domain_corners(const PlacedFace& f) {
  if (is_triangle(f)) return {{0, 0}, {1, 0}, {0, 1}};
  return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
}

Eigen::Vector2d domain_centre(const PlacedFace& f) {
  const FaceDef& face = f.element->faces()[f.face];
  if (face.axis >= 0) return Eigen::Vector2d::Zero();
  const std::array<double, 2> c = FaceParam(*f.element, face).centre();
  return {c[0], c[1]};
}

// The slave face's auxiliary plane: its tangent plane at the face centre, with in-plane axes
// (e1, e2) such that (e1, e2, normal) is right-handed and normal points out of the slave body.
struct Plane {
  Eigen::Vector3d origin, e1, e2, normal;
  Eigen::Vector2d coordinates(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d d = x - origin;
    return {d.dot(e1), d.dot(e2)};
  }
};

Plane auxiliary_plane(const PlacedFace& slave) {
  const Eigen::Vector2d c = domain_centre(slave);
  Eigen::Vector3d x, xp, xq;
  face_map(slave, c[0], c[1], x, xp, xq);
  Plane plane;
  plane.origin = x;
  plane.normal = outward_normal(slave, c[0], c[1]);
  plane.e1 = (xp - xp.dot(plane.normal) * plane.normal).normalized();
  plane.e2 = plane.normal.cross(plane.e1);
  return plane;
}

Eigen::Vector2d projected_point(const PlacedFace& f, const Plane& plane,
                                const Eigen::Vector2d& pq) {
  Eigen::Vector3d x, xp, xq;
  face_map(f, pq[0], pq[1], x, xp, xq);
  return plane.coordinates(x);
}

// The face's boundary projected onto the plane: its corners, and chords along the edges whose
// projection is curved (straight edges, those of flat faces among them, stay exact).
Polygon projected_boundary(const PlacedFace& f, const Plane& plane) {
  const Polygon corners = domain_corners(f);
  Polygon out;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d& a = corners[i];
    const Eigen::Vector2d& b = corners[(i + 1) % corners.size()];
    const Eigen::Vector2d ya = projected_point(f, plane, a), yb = projected_point(f, plane, b);
    const Eigen::Vector2d chord = yb - ya;
    bool straight = true;
    for (const double t : {0.25, 0.5, 0.75}) {
      const Eigen::Vector2d y = projected_point(f, plane, a + t * (b - a));
      if (std::abs(cross(chord, y - ya)) > 1e-12 * chord.squaredNorm()) straight = false;
    }
    const int chords = straight ? 1 : kCurvedEdgeChords;
    for (int k = 0; k < chords; ++k)
      out.push_back(projected_point(f, plane, a + (b - a) * (static_cast<double>(k) / chords)));
  }
  return out;
}

double signed_area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice;
}

Polygon counter_clockwise(Polygon polygon) {
  if (signed_area(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// Sutherland-Hodgman: the part of `subject` inside the convex counter-clockwise polygon `clip`.
// Points within round-off of a clip edge count as inside, so edges the two meshes share (the
// patch's outline, coincident element edges) neither lose vertices nor create spurious ones.
Polygon clip_polygon(Polygon subject, const Polygon& clip, double length) {
  const double tolerance = 1e-12 * length * length;
  for (std::size_t i = 0; i < clip.size() && subject.size() >= 3; ++i) {
    const Eigen::Vector2d& a = clip[i];
    const Eigen::Vector2d& b = clip[(i + 1) % clip.size()];
    auto side = [&](const Eigen::Vector2d& x) {
      const double s = cross(b - a, x - a);
      return std::abs(s) <= tolerance ? 0.0 : s;
    };
    Polygon kept;
    for (std::size_t j = 0; j < subject.size(); ++j) {
      const Eigen::Vector2d& p = subject[j];
      const Eigen::Vector2d& q = subject[(j + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) kept.push_back(p);
      if ((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0))
        kept.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    subject = std::move(kept);
  }
  return subject;
}

// The in-face coordinates of the face point that projects onto plane point y along the plane's
// normal (Newton from the face centre; one step for an affine face). `area_ratio` (may be null)
// receives dA_face / dA_plane there. False when Newton does not converge.
bool plane_inverse(const PlacedFace& f, const Plane& plane, const Eigen::Vector2d& y,
                   Eigen::Vector2d& pq, double* area_ratio) {
  pq = domain_centre(f);
  Eigen::Vector3d x, xp, xq;
  for (int iteration = 0; iteration < 40; ++iteration) {
    face_map(f, pq[0], pq[1], x, xp, xq);
    Eigen::Matrix2d J;
    J << plane.e1.dot(xp), plane.e1.dot(xq), plane.e2.dot(xp), plane.e2.dot(xq);
    const Eigen::Vector2d step = J.inverse() * (y - plane.coordinates(x));
    if (!step.allFinite()) return false;
    pq += step;
    if (step.lpNorm<Eigen::Infinity>() < 1e-13) {
      face_map(f, pq[0], pq[1], x, xp, xq);
      J << plane.e1.dot(xp), plane.e1.dot(xq), plane.e2.dot(xp), plane.e2.dot(xq);
      if (area_ratio != nullptr) *area_ratio = xp.cross(xq).norm() / std::abs(J.determinant());
      return true;
    }
  }
  return false;
}

// The slave basis N^ at (p, q).
Eigen::VectorXd slave_basis_values(const MortarFace& f, double p, double q) {
  const Eigen::VectorXd N = face_shape_values(f, p, q);
  return f.basis.size() > 0 ? Eigen::VectorXd(f.basis * N) : N;
}

// integral N^_a dA per face node, and the face's mass matrix integral N^_a N^_b dA (may be null).
Eigen::VectorXd nodal_integrals(const MortarFace& slave, Eigen::MatrixXd* mass) {
  const int n = static_cast<int>(slave.local.size());
  if (mass != nullptr) mass->setZero(n, n);
  Eigen::VectorXd integrals = Eigen::VectorXd::Zero(n);
  const FaceRule rule = face_rule(is_triangle(slave.placed), kFaceOrder);
  for (std::size_t g = 0; g < rule.points.size(); ++g) {
    const auto [p, q] = rule.points[g];
    Eigen::Vector3d x, xp, xq;
    face_map(slave.placed, p, q, x, xp, xq);
    const double dA = rule.weights[g] * xp.cross(xq).norm();
    const Eigen::VectorXd N = slave_basis_values(slave, p, q);
    if (mass != nullptr) mass->noalias() += dA * N * N.transpose();
    integrals += dA * N;
  }
  return integrals;
}

// The first node with a non-positive integral, -1 if none.
int first_non_positive(const Eigen::VectorXd& integrals) {
  for (int a = 0; a < integrals.size(); ++a)
    if (!(integrals[a] > 1e-9 * integrals.sum())) return a;
  return -1;
}

}  // namespace

Eigen::Vector3d face_centre_normal(const PlacedFace& f) {
  const Eigen::Vector2d c = domain_centre(f);
  return outward_normal(f, c[0], c[1]);
}

Eigen::VectorXd face_shape_values(const MortarFace& f, double p, double q) {
  const Eigen::VectorXd all = shape_values(*f.placed.element, face_point(f.placed, p, q));
  Eigen::VectorXd out(f.local.size());
  for (std::size_t a = 0; a < f.local.size(); ++a) out[a] = all[f.local[a]];
  return out;
}

Eigen::MatrixXd slave_basis_transform(const MortarFace& f) {
  // The corners' share of a mid-edge node (Popp et al. 2012: 1/5 for both face types).
  constexpr double kShare = 0.2;
  const int n = static_cast<int>(f.local.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(n, n);
  const int corners = is_triangle(f.placed) ? 3 : 4;
  if (n != 2 * corners) return T;
  const std::vector<Vec3>& xi = f.placed.element->natural_nodes();
  auto natural = [&](int a) {
    return Eigen::Vector3d(xi[f.local[a]][0], xi[f.local[a]][1], xi[f.local[a]][2]);
  };
  for (int m = corners; m < n; ++m)
    for (int a = 0; a < corners; ++a)
      for (int b = a + 1; b < corners; ++b)
        if ((natural(a) + natural(b) - 2.0 * natural(m)).norm() < 1e-12) {
          T(m, m) = 1.0 - 2.0 * kShare;
          T(a, m) = T(b, m) = kShare;
        }
  return T;
}

bool admits_dual_basis(const MortarFace& slave) {
  return first_non_positive(nodal_integrals(slave, nullptr)) < 0;
}

DualBasis dual_basis(const MortarFace& slave, const SourceLoc& where) {
  Eigen::MatrixXd mass;
  const Eigen::VectorXd integrals = nodal_integrals(slave, &mass);
  if (const int a = first_non_positive(integrals); a >= 0)
    throw InputError(where, "TYPE=MORTAR: face S" + std::to_string(slave.placed.face + 1) +
                                " of slave element " + std::to_string(slave.placed.geometry.id) +
                                " has a node whose integral of N dA is not positive (" +
                                std::to_string(integrals[a]) +
                                "), which dual multipliers cannot carry; give the slave side a "
                                "C3D21/C3D28 contact layer or make it the master");
  DualBasis out;
  out.nodal_integrals = integrals;
  // phi = D M^-1 N with M the face's mass matrix and D = diag(integrals): then
  // integral phi_a N_b dA = (D M^-1 M)_ab = D_a delta_ab.
  out.coefficients = mass.ldlt().solve(Eigen::MatrixXd(integrals.asDiagonal())).transpose();
  return out;
}

double integrate_overlap(const MortarFace& slave, const DualBasis& dual, const MortarFace& master,
                         Eigen::MatrixXd& coupling) {
  const Plane plane = auxiliary_plane(slave.placed);
  const Polygon slave_outline = counter_clockwise(projected_boundary(slave.placed, plane));
  const double slave_area = signed_area(slave_outline);
  const Polygon overlap = clip_polygon(counter_clockwise(projected_boundary(master.placed, plane)),
                                       slave_outline, std::sqrt(slave_area));
  if (overlap.size() < 3) return 0.0;
  const double area = signed_area(overlap);
  if (area <= 1e-12 * slave_area) return 0.0;
  // The overlap as a fan of triangles from its first vertex; signed areas keep the sum exact for
  // a polygon that chords of curved edges leave slightly non-convex.
  const FaceRule rule = face_rule(true, kOverlapOrder);
  Eigen::Vector2d slave_pq, master_pq;
  for (std::size_t i = 1; i + 1 < overlap.size(); ++i) {
    const Eigen::Vector2d& origin = overlap[0];
    const Eigen::Vector2d u = overlap[i] - origin, v = overlap[i + 1] - origin;
    const double jacobian = cross(u, v);  // twice the triangle's signed area
    if (jacobian == 0.0) continue;
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const Eigen::Vector2d y = origin + rule.points[g][0] * u + rule.points[g][1] * v;
      double ratio = 0.0;
      if (!plane_inverse(slave.placed, plane, y, slave_pq, &ratio) ||
          !plane_inverse(master.placed, plane, y, master_pq, nullptr))
        continue;
      const Eigen::VectorXd phi =
          dual.coefficients * slave_basis_values(slave, slave_pq[0], slave_pq[1]);
      const Eigen::VectorXd N = face_shape_values(master, master_pq[0], master_pq[1]);
      coupling.noalias() += (rule.weights[g] * jacobian * ratio) * phi * N.transpose();
    }
  }
  return area;
}

}  // namespace styk::contact
