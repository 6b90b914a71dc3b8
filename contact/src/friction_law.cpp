#include "styk/contact/friction_law.hpp"

#include <algorithm>
#include <cmath>

namespace styk::contact {
namespace {

// b = lambda_n + c_n (overclosure beyond what the penalty spring carries): the second term is 0
// on a closed node at a solution.
double normal_indicator(const LocalPoint& p) {
  return p.lambda[0] + p.c_n * (p.d[0] - p.gap0 - spring_overclosure(p, p.lambda[0]));
}

bool exponential(const LocalPoint& p) { return p.exponential_force0 > 0.0; }

// Tangential part with the components that do not take part masked to zero.
Eigen::Vector2d masked(const LocalPoint& p, const Eigen::Vector3d& v) {
  return {p.live[1] ? v[1] : 0.0, p.live[2] ? v[2] : 0.0};
}

Eigen::Vector2d trial_traction(const LocalPoint& p) {
  return masked(p, p.lambda) + p.c_t * (masked(p, p.d) - masked(p, p.d_ref));
}

bool has_tangential(const LocalPoint& p) { return p.live[1] || p.live[2]; }

}  // namespace

double exponential_least_force(const LocalPoint& p) {
  return exponential(p) ? p.exponential_force0 / 100.0 : 0.0;  // p0 drops to 1 % at c0
}

double spring_overclosure(const LocalPoint& p, double lambda_n) {
  if (!exponential(p)) return p.compliance * lambda_n;
  const double force = std::max(lambda_n, exponential_least_force(p));
  return std::log(force / p.exponential_force0) / p.exponential_beta;
}

SpringTangent spring_tangent(const LocalPoint& p) {
  if (!exponential(p)) return {p.compliance, 0.0};
  const double at = std::max(p.lambda[0], exponential_least_force(p));
  SpringTangent tangent;
  tangent.compliance = 1.0 / (p.exponential_beta * at);
  tangent.offset = spring_overclosure(p, at) - tangent.compliance * at;
  return tangent;
}

const char* status_name(NodeStatus status) {
  switch (status) {
    case NodeStatus::Open:
      return "open";
    case NodeStatus::Stick:
      return "stick";
    case NodeStatus::Slip:
      return "slip";
  }
  return "?";
}

NodeStatus classify(const LocalPoint& p) {
  if (p.bonded) return NodeStatus::Stick;
  const double b = normal_indicator(p);
  if (!(b > p.eps)) return NodeStatus::Open;
  // Frictionless closed nodes slide freely: "slip" with no tangential force.
  if (!has_tangential(p)) return p.frictional || p.tied ? NodeStatus::Stick : NodeStatus::Slip;
  if (p.tied) return NodeStatus::Stick;
  return trial_traction(p).norm() <= b ? NodeStatus::Stick : NodeStatus::Slip;
}

Eigen::Vector2d slip_function(const LocalPoint& p) {
  const Eigen::Vector2d xi = trial_traction(p);
  return masked(p, p.lambda) - normal_indicator(p) * xi / xi.norm();
}

LocalRows linearise(const LocalPoint& p, NodeStatus status) {
  LocalRows rows;
  if (status == NodeStatus::Open) {
    rows.D.setIdentity();
    return rows;
  }
  // d_n - e lambda_n = gap0 + offset: the spring's overclosure linearised at the iterate.
  const SpringTangent penalty = spring_tangent(p);
  rows.Q(0, 0) = 1.0;
  rows.D(0, 0) = -penalty.compliance;
  rows.r[0] = p.gap0 + penalty.offset;
  if (p.bonded) {
    for (int k = 1; k < 3; ++k) {
      rows.Q(k, k) = 1.0;  // d_t - e lambda_t = 0: a spring from the initial position
      rows.D(k, k) = -p.compliance;
    }
  } else if (status == NodeStatus::Stick) {
    for (int k = 1; k < 3; ++k) {
      rows.Q(k, k) = 1.0;  // d_t = d_t_ref
      rows.r[k] = p.d_ref[k];
    }
  } else if (has_tangential(p)) {
    // Exact derivative of F = lambda_t - b xi / |xi| at the iterate, with
    // dxi = d lambda_t + c_t d d_t, db = d lambda_n + c_n d d_n and P = I - e e^T, e = xi / |xi|:
    //   dF = (I - beta P) d lambda_t - e d lambda_n - c_n e d d_n - beta c_t P d d_t,
    // beta = b / |xi| < 1 in slip; written for the new values (P xi = 0 simplifies r).
    const Eigen::Vector2d xi = trial_traction(p);
    const double length = xi.norm();
    const double beta = normal_indicator(p) / length;
    const Eigen::Vector2d e = xi / length;
    const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - e * e.transpose();
    const Eigen::Vector2d dref = masked(p, p.d_ref);
    // db = (1 - c_n e_pen) d lambda_n + c_n d d_n (e_pen: the penalty compliance at the
    // iterate; b's constant part moves gap0 by the spring's offset).
    rows.D.block<2, 1>(1, 0) = -(1.0 - p.c_n * penalty.compliance) * e;
    rows.D.block<2, 2>(1, 1) = Eigen::Matrix2d::Identity() - beta * P;
    rows.Q.block<2, 1>(1, 0) = -p.c_n * e;
    rows.Q.block<2, 2>(1, 1) = -beta * p.c_t * P;
    rows.r.tail<2>() = -p.c_n * (p.gap0 + penalty.offset) * e - beta * p.c_t * P * dref;
    if (p.proximal > 0.0) {
      const Eigen::Matrix2d spring = p.proximal * p.c_t * e * e.transpose();
      rows.Q.block<2, 2>(1, 1) -= spring;
      rows.r.tail<2>() -= spring * masked(p, p.d);
    }
  }
  for (int k = 1; k < 3; ++k)
    if (!p.live[k]) {
      rows.Q.row(k).setZero();
      rows.D.row(k).setZero();
      rows.D(k, k) = 1.0;
      rows.r[k] = 0.0;
    }
  return rows;
}

double cone_ratio(const LocalPoint& p) {
  if (p.bonded || p.tied || !has_tangential(p)) return 0.0;
  const double b = normal_indicator(p);
  if (!(b > p.eps)) return 0.0;
  return trial_traction(p).norm() / b;
}

Eigen::Vector2d traction_on_cone(const LocalPoint& p) {
  const Eigen::Vector2d xi = trial_traction(p);
  const double length = xi.norm();
  if (cone_ratio(p) == 0.0 || !(length > 0.0)) return Eigen::Vector2d::Zero();
  return normal_indicator(p) * xi / length;
}

Eigen::Vector3d complementarity_residual(const LocalPoint& p) {
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
  if (p.bonded) {
    // lambda = (d - gap0 n) / e in every live component, in force units.
    residual[0] = p.lambda[0] - (p.d[0] - p.gap0) / p.compliance;
    for (int k = 1; k < 3; ++k)
      if (p.live[k]) residual[k] = p.lambda[k] - p.d[k] / p.compliance;
    return residual;
  }
  const double b = normal_indicator(p);
  residual[0] = p.lambda[0] - std::max(0.0, b);
  if (!has_tangential(p)) return residual;
  const Eigen::Vector2d a = masked(p, p.lambda);
  const Eigen::Vector2d xi = trial_traction(p);
  Eigen::Vector2d projected = xi;
  if (!(b > p.eps)) {
    projected.setZero();
  } else if (!p.tied) {
    const double radius = std::max(p.lambda[0], 0.0);
    if (xi.norm() > radius) projected = xi * (radius / xi.norm());
  }
  residual.tail<2>() = a - projected;
  return residual;
}

}  // namespace styk::contact
