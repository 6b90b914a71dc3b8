#include "styk/studies/study/exact_solution.hpp"

#include <cmath>
#include <stdexcept>

namespace styk::studies {
namespace {

// Cartesian components of a stress given in polar components about z at angle theta (sigma_zz,
// no shear out of the plane).
Tensor6 from_polar(double srr, double stt, double srt, double szz, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {srr * c * c + stt * s * s - 2 * srt * s * c,
          srr * s * s + stt * c * c + 2 * srt * s * c,
          szz,
          (srr - stt) * s * c + srt * (c * c - s * s),
          0.0,
          0.0};
}

Vec3 from_polar(double ur, double ut, double uz, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {ur * c - ut * s, ur * s + ut * c, uz};
}

// One Lamé ring: sigma_rr = A - B/r^2, sigma_tt = A + B/r^2 (plane strain).
struct LameRing {
  double A = 0, B = 0, E = 1, nu = 0;
  LameRing() = default;
  LameRing(double a, double b, double pa, double pb, double young, double poisson)
      : A((pa * a * a - pb * b * b) / (b * b - a * a)),
        B((pa - pb) * a * a * b * b / (b * b - a * a)),
        E(young),
        nu(poisson) {}
  double ur(double r) const { return (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r); }
  Vec3 displacement(const Vec3& x) const {
    const double r = std::hypot(x[0], x[1]);
    return from_polar(ur(r), 0.0, 0.0, std::atan2(x[1], x[0]));
  }
  Tensor6 stress(const Vec3& x) const {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    return from_polar(A - B / r2, A + B / r2, 0.0, 2 * nu * A, std::atan2(x[1], x[0]));
  }
};

class Lame final : public ExactSolution {
 public:
  explicit Lame(LameRing ring) : ring_(ring) {}
  Vec3 displacement(const Vec3& x, int) const override { return ring_.displacement(x); }
  Tensor6 stress(const Vec3& x, int) const override { return ring_.stress(x); }
  double young(int) const override { return ring_.E; }
  double poisson(int) const override { return ring_.nu; }

 private:
  LameRing ring_;
};

class Compound final : public CompoundCylinders {
 public:
  Compound(double a, double c, double b, double pa, double pb, double E1, double nu1, double E2,
           double nu2) {
    // u_r(c) of each ring is affine in the contact pressure q: solve inner(q) = outer(q).
    auto mismatch = [&](double q) {
      return LameRing(a, c, pa, q, E1, nu1).ur(c) - LameRing(c, b, q, pb, E2, nu2).ur(c);
    };
    const double m0 = mismatch(0), m1 = mismatch(1);
    q_ = -m0 / (m1 - m0);
    inner_ = LameRing(a, c, pa, q_, E1, nu1);
    outer_ = LameRing(c, b, q_, pb, E2, nu2);
  }
  double contact_pressure() const override { return q_; }
  Vec3 displacement(const Vec3& x, int region) const override {
    return ring(region).displacement(x);
  }
  Tensor6 stress(const Vec3& x, int region) const override { return ring(region).stress(x); }
  double young(int region) const override { return ring(region).E; }
  double poisson(int region) const override { return ring(region).nu; }

 private:
  const LameRing& ring(int region) const {
    if (region != 0 && region != 1)
      throw std::logic_error("compound cylinders: region " + std::to_string(region));
    return region == 0 ? inner_ : outer_;
  }
  double q_ = 0;
  LameRing inner_, outer_;
};

class Cantilever final : public ExactSolution {
 public:
  Cantilever(double L, double h, double b, double P, double E)
      : L_(L), c_(h / 2), P_(P), E_(E), I_(b * h * h * h / 12) {}
  Vec3 displacement(const Vec3& p, int) const override {
    const double x = p[0], y = p[2] - c_, k = P_ / (E_ * I_);
    return {-k * y * (L_ * x - x * x / 2) + k * (c_ * c_ * y - y * y * y / 3), 0.0,
            k * (L_ * x * x / 2 - x * x * x / 6)};
  }
  Tensor6 stress(const Vec3& p, int) const override {
    const double x = p[0], y = p[2] - c_;
    return {-P_ * (L_ - x) * y / I_, 0.0, 0.0, 0.0, P_ * (c_ * c_ - y * y) / (2 * I_), 0.0};
  }
  double young(int) const override { return E_; }
  double poisson(int) const override { return 0.0; }

 private:
  double L_, c_, P_, E_, I_;
};

class CurvedBar final : public ExactSolution {
 public:
  CurvedBar(double a, double b, double t, double P, double E) : E_(E) {
    // Traction-free curved faces: g(r) = 2 A r - 2 B / r^3 + D / r = 0 at r = a, b; the end
    // shear sums to P / t per unit thickness: [A r^2 + B / r^2 + D ln r]_a^b = P / t.
    const double N = b * b - a * a + (a * a + b * b) * std::log(a / b), Pt = P / t;
    A_ = Pt / (2 * N);
    B_ = -Pt * a * a * b * b / (2 * N);
    D_ = -Pt * (a * a + b * b) / N;
  }
  Vec3 displacement(const Vec3& x, int) const override {
    const double r = std::hypot(x[0], x[1]), th = std::atan2(x[1], x[0]);
    const double c = std::cos(th), s = std::sin(th), lr = std::log(r);
    // nu = 0 in the plane-stress displacements of the cos(theta) stress function.
    const double ur = 2 * D_ / E_ * th * s + c / E_ * (D_ * lr + A_ * r * r + B_ / (r * r));
    const double ut =
        2 * D_ / E_ * th * c + s / E_ * (5 * A_ * r * r + B_ / (r * r) - D_ * lr) - D_ / E_ * s;
    return from_polar(ur, ut, 0.0, th);
  }
  Tensor6 stress(const Vec3& x, int) const override {
    const double r = std::hypot(x[0], x[1]), th = std::atan2(x[1], x[0]);
    const double g = 2 * A_ * r - 2 * B_ / (r * r * r) + D_ / r;
    const double f2 = 6 * A_ * r + 2 * B_ / (r * r * r) + D_ / r;
    return from_polar(g * std::cos(th), f2 * std::cos(th), g * std::sin(th), 0.0, th);
  }
  double young(int) const override { return E_; }
  double poisson(int) const override { return 0.0; }

 private:
  double E_, A_ = 0, B_ = 0, D_ = 0;
};

class WallHeat final : public ExactSolution {
 public:
  WallHeat(double r1, double r2, double T1, double T2, double k)
      : r1_(r1), T1_(T1), slope_((T1 - T2) / std::log(r2 / r1)), k_(k) {}
  bool scalar() const override { return true; }
  double temperature(const Vec3& x) const override {
    return T1_ - slope_ * std::log(std::hypot(x[0], x[1]) / r1_);
  }
  Vec3 gradient(const Vec3& x) const override {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    return {-slope_ * x[0] / r2, -slope_ * x[1] / r2, 0.0};
  }
  double conductivity() const override { return k_; }
  double young(int) const override { return 1.0; }
  double poisson(int) const override { return 0.0; }

 private:
  double r1_, T1_, slope_, k_;
};

}  // namespace

Vec3 ExactSolution::displacement(const Vec3&, int) const {
  throw std::logic_error("exact solution: a scalar field has no displacement");
}
Tensor6 ExactSolution::stress(const Vec3&, int) const {
  throw std::logic_error("exact solution: a scalar field has no stress");
}
double ExactSolution::temperature(const Vec3&) const {
  throw std::logic_error("exact solution: a mechanical field has no temperature");
}
Vec3 ExactSolution::gradient(const Vec3&) const {
  throw std::logic_error("exact solution: a mechanical field has no temperature gradient");
}

std::unique_ptr<ExactSolution> lame_cylinder(double a, double b, double pa, double pb, double E,
                                             double nu) {
  return std::make_unique<Lame>(LameRing(a, b, pa, pb, E, nu));
}

std::unique_ptr<CompoundCylinders> compound_cylinders(double a, double c, double b, double pa,
                                                      double pb, double E1, double nu1, double E2,
                                                      double nu2) {
  return std::make_unique<Compound>(a, c, b, pa, pb, E1, nu1, E2, nu2);
}

std::unique_ptr<ExactSolution> timoshenko_cantilever(double L, double h, double b, double P,
                                                     double E) {
  return std::make_unique<Cantilever>(L, h, b, P, E);
}

std::unique_ptr<ExactSolution> curved_bar(double a, double b, double t, double P, double E) {
  return std::make_unique<CurvedBar>(a, b, t, P, E);
}

std::unique_ptr<ExactSolution> cylinder_wall_heat(double r1, double r2, double T1, double T2,
                                                  double k) {
  return std::make_unique<WallHeat>(r1, r2, T1, T2, k);
}

}  // namespace styk::studies
