#include "contact/PairContact.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "loads/FaceShape.hpp"

namespace glossa::contact {

namespace {

// The n Gauss-Legendre nodes and weights on [-1, 1]: Newton on P_n from Chebyshev's guesses,
// P_n and P_n' by the three-term recurrence.
std::vector<std::pair<double, double>> gaussLegendre(int n) {
  std::vector<std::pair<double, double>> rule(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dP = 1.0;
    for (int it = 0; it < 100; ++it) {
      double P0 = 1.0, P1 = x;
      for (int k = 2; k <= n; ++k) {
        const double P2 = ((2.0 * k - 1.0) * x * P1 - (k - 1.0) * P0) / k;
        P0 = P1;
        P1 = P2;
      }
      dP = n * (x * P1 - P0) / (x * x - 1.0);
      const double dx = P1 / dP;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule[static_cast<std::size_t>(i)] = {x, 2.0 / ((1.0 - x * x) * dP * dP)};
  }
  return rule;
}

// The bilinear face's second derivative x_,st (x_,ss = x_,tt = 0): sum_a s_a t_a / 4 x_a.
Eigen::Vector3d twist(const loads::FaceNodes &x) {
  const Eigen::Vector4d st(0.25, -0.25, 0.25, -0.25);
  return x.transpose() * st;
}

}  // namespace

std::vector<SlavePoint> slavePoints(int n) {
  if (n < 1)
    throw std::invalid_argument("slavePoints: " + std::to_string(n) + " points per direction; at least 1");
  const auto rule = gaussLegendre(n);
  std::vector<SlavePoint> points;
  for (const auto &[t, wt] : rule)
    for (const auto &[s, ws] : rule) points.push_back({Eigen::Vector2d(s, t), ws * wt});
  return points;
}

std::optional<FaceProjection> projectOntoFace(const loads::FaceNodes &xm, const Eigen::Vector3d &x) {
  // Minimise |x - x_m(s, t)|^2: r_a = (x - x_m) . a_a = 0 with a_1 = x_,s, a_2 = x_,t; its
  // Jacobian A = [a_a . a_b] - (x - x_m) . x_,st on the off-diagonal (a bilinear face has no
  // x_,ss or x_,tt).
  const Eigen::Vector3d xst = twist(xm);
  const double size = (xm.row(2) - xm.row(0)).norm() + (xm.row(3) - xm.row(1)).norm();
  Eigen::Vector2d st = Eigen::Vector2d::Zero();
  for (int it = 0; it < 30; ++it) {
    const loads::FaceShape shape = loads::faceShape(st(0), st(1));
    const Eigen::Vector3d d = x - xm.transpose() * shape.N;
    const Eigen::Vector3d a1 = xm.transpose() * shape.dNds, a2 = xm.transpose() * shape.dNdt;
    Eigen::Matrix2d A;
    A << a1.dot(a1), a1.dot(a2) - d.dot(xst), a1.dot(a2) - d.dot(xst), a2.dot(a2);
    const Eigen::Vector2d r(d.dot(a1), d.dot(a2));
    const Eigen::Vector2d step = A.fullPivLu().solve(r);
    if (!step.allFinite()) return std::nullopt;
    st += step;
    if (step.norm() < 1e-14 * std::max(1.0, st.norm())) {
      const loads::FaceShape at = loads::faceShape(st(0), st(1));
      const Eigen::Vector3d c = (xm.transpose() * at.dNds).cross(xm.transpose() * at.dNdt);
      if (!(c.norm() > 1e-300 * size * size)) return std::nullopt;
      FaceProjection p;
      p.st = st;
      p.normal = c.normalized();
      p.gap = (x - xm.transpose() * at.N).dot(p.normal);
      p.inside = st.cwiseAbs().maxCoeff() <= 1.0 + 1e-10;
      return p;
    }
    // Far outside the face the closest point of the bilinear extension means nothing.
    if (st.cwiseAbs().maxCoeff() > 10.0) return std::nullopt;
  }
  return std::nullopt;
}

PairForces pairPointForces(const loads::FaceNodes &xs, const SlavePoint &q, const loads::FaceNodes &xm,
                           double lambda, double eps, ContactPointState *point, PairTangent *K) {
  PairForces f = PairForces::Zero();
  if (K) K->setZero();
  const loads::FaceShape sh = loads::faceShape(q.st(0), q.st(1));
  const Eigen::Vector3d x = xs.transpose() * sh.N;
  const Eigen::Vector3d xs1 = xs.transpose() * sh.dNds, xs2 = xs.transpose() * sh.dNdt;
  const Eigen::Vector3d areaVector = xs1.cross(xs2);
  const double j = areaVector.norm();
  ContactPointState state;
  state.gap = std::numeric_limits<double>::infinity();
  state.area = q.weight * j;
  const std::optional<FaceProjection> p = projectOntoFace(xm, x);
  if (!p || !p->inside) {
    if (point) *point = state;
    return f;
  }
  state.gap = p->gap;
  const double trial = lambda - eps * p->gap, t = std::max(0.0, trial);
  state.pressure = t;
  if (point) *point = state;
  if (trial < 0.0) return f;

  const Eigen::Vector3d &n = p->normal;
  const loads::FaceShape mh = loads::faceShape(p->st(0), p->st(1));
  const double w = q.weight;
  for (int a = 0; a < 4; ++a) {
    f.segment<3>(3 * a) = w * t * j * sh.N(a) * n;
    f.segment<3>(12 + 3 * a) = -w * t * j * mh.N(a) * n;
  }
  if (!K || j == 0.0) return f;

  // Derivatives in the 24 dofs: of x_s, of x_m at fixed (s, t), and of a_1, a_2 at fixed (s, t).
  using Dofs = Eigen::Matrix<double, 3, 24>;
  Dofs Dxs = Dofs::Zero(), Dxm = Dofs::Zero(), Da1 = Dofs::Zero(), Da2 = Dofs::Zero();
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int b = 0; b < 4; ++b) {
    Dxs.block<3, 3>(0, 3 * b) = sh.N(b) * I;
    Dxm.block<3, 3>(0, 12 + 3 * b) = mh.N(b) * I;
    Da1.block<3, 3>(0, 12 + 3 * b) = mh.dNds(b) * I;
    Da2.block<3, 3>(0, 12 + 3 * b) = mh.dNdt(b) * I;
  }
  const Eigen::Vector3d a1 = xm.transpose() * mh.dNds, a2 = xm.transpose() * mh.dNdt, xst = twist(xm);
  const double g = p->gap;
  // The projection's variation, from d r_a = 0 with x_s - x_m = g n:
  //   A d(s, t) = a_a . (dx_s - dx_m) + g n . da_a,   A = [a_a . a_b] - g n . x_,st off the diagonal.
  Eigen::Matrix2d A;
  A << a1.dot(a1), a1.dot(a2) - g * n.dot(xst), a1.dot(a2) - g * n.dot(xst), a2.dot(a2);
  const Dofs Dd = Dxs - Dxm;
  Eigen::Matrix<double, 2, 24> rhs;
  rhs.row(0) = a1.transpose() * Dd + g * n.transpose() * Da1;
  rhs.row(1) = a2.transpose() * Dd + g * n.transpose() * Da2;
  const Eigen::Matrix<double, 2, 24> dst = A.inverse() * rhs;
  // The normal's variation, its tangents moving with the nodes and with (s, t): a_1,t = a_2,s = x_,st.
  const Dofs dA1 = Da1 + xst * dst.row(1), dA2 = Da2 + xst * dst.row(0);
  const Eigen::Vector3d c = a1.cross(a2);
  const Dofs dn =
      (I - n * n.transpose()) / c.norm() * (-loads::crossMatrix(a2) * dA1 + loads::crossMatrix(a1) * dA2);
  // dg = n . (dx_s - dx_m): the terms in d(s, t) and dn vanish at the closest point.
  const Eigen::Matrix<double, 1, 24> dt = -eps * n.transpose() * Dd;
  // The slave area element: dj/du_b = m^T (dN_b/dt [x_,s]_x - dN_b/ds [x_,t]_x), m its unit normal.
  Eigen::Matrix<double, 1, 24> dj = Eigen::Matrix<double, 1, 24>::Zero();
  const Eigen::RowVector3d mT = areaVector.transpose() / j;
  const Eigen::Matrix3d S1 = loads::crossMatrix(xs1), S2 = loads::crossMatrix(xs2);
  for (int b = 0; b < 4; ++b) dj.segment<3>(3 * b) = mT * (sh.dNdt(b) * S1 - sh.dNds(b) * S2);
  // d(t j n) at the point, shared by both faces' rows.
  const Dofs dtjn = n * (j * dt + t * dj) + t * j * dn;
  for (int a = 0; a < 4; ++a) {
    K->block<3, 24>(3 * a, 0) = w * sh.N(a) * dtjn;
    K->block<3, 24>(12 + 3 * a, 0) =
        -w * (mh.N(a) * dtjn + t * j * n * (mh.dNds(a) * dst.row(0) + mh.dNdt(a) * dst.row(1)));
  }
  return f;
}

}  // namespace glossa::contact
