#include "fem/Q1P0Element.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace glossa::fem {

namespace {

using materials::Tangent9;

struct PointKinematics {
  Eigen::Matrix<double, 8, 3> dNdX;
  double dV = 0.0; // reference volume weight
  Eigen::Matrix3d F;
  Eigen::Matrix3d Finv; // valid when J > 0
  double J = 1.0;
};

Eigen::Matrix<double, 9, 1> flatten(const Eigen::Matrix3d &M) {
  Eigen::Matrix<double, 9, 1> v;
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) v(i * 3 + J) = M(i, J);
  return v;
}

// d(J F^{-T})_iJ / dF_kL = J (Finv_Ji Finv_Lk - Finv_Jk Finv_Li)
Tangent9 cofactorDerivative(const Eigen::Matrix3d &Finv, double J) {
  Tangent9 D;
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          D(i * 3 + J_, k * 3 + L) = J * (Finv(J_, i) * Finv(L, k) - Finv(J_, k) * Finv(L, i));
  return D;
}

// Kinematics at the 8 Gauss points; false if the reference element is degenerate.
bool kinematics(const NodeMatrix &X, const NodeMatrix &u, std::array<PointKinematics, 8> &pts,
                double &minJ) {
  const auto &rule = gaussHex2();
  minJ = std::numeric_limits<double>::infinity();
  for (int q = 0; q < 8; ++q) {
    double detJ0 = 0.0;
    if (!hexGradients(X, rule[q].xi, pts[q].dNdX, detJ0)) return false;
    pts[q].dV = detJ0 * rule[q].weight;
    pts[q].F = Eigen::Matrix3d::Identity() + u.transpose() * pts[q].dNdX;
    pts[q].J = pts[q].F.determinant();
    if (pts[q].J > 0.0) pts[q].Finv = pts[q].F.inverse();
    minJ = std::min(minJ, pts[q].J);
  }
  return true;
}

// Which part of an element's tangent a point adds: every block, or (a hyperelastic point law, whose
// A is symmetric) the blocks K_ab with b >= a only, the others mirrored once the element's points
// are in (mirrorUpperBlocks). The upper blocks are 36 of the 64: 0.6x the flops of this kernel.
enum class TangentBlocks { all, upper };

// Node a's rows of the blocks K_ab, b >= a: columns 3a to 23, a width fixed at compile time so
// that the row products stay vectorised (a 3x3 block at a time ran slower than all 64 blocks).
template <int A>
void addUpperRows(ElementMatrix &tangent, const Eigen::Matrix<double, 9, 24> &AB, const Eigen::Matrix<double, 8, 3> &dN,
                  double dV) {
  constexpr int width = 24 - 3 * A;
  const Eigen::RowVector3d w = dV * dN.row(A);
  for (int i = 0; i < 3; ++i)
    tangent.block<1, width>(3 * A + i, 3 * A).noalias() += w * AB.block<3, width>(3 * i, 3 * A);
  if constexpr (A < 7) addUpperRows<A + 1>(tangent, AB, dN, dV);
}

void addPoint(ElementVector &residual, ElementMatrix &tangent, Eigen::Matrix3d &cauchyIntegral,
              const PointKinematics &pt, const Eigen::Matrix3d &P, const Tangent9 &A, Q1P0Output what,
              TangentBlocks blocks = TangentBlocks::all) {
  // R_a = P dN_a/dX; K_ab(i,k) = sum_JL dN_a/dX_J A(iJ,kL) dN_b/dX_L, using the sparsity of the
  // gradient operator B (a third of the flops of the dense B^T A B).
  const Eigen::Matrix<double, 8, 3> &dN = pt.dNdX;
  for (int a = 0; a < 8; ++a) residual.segment<3>(3 * a).noalias() += P * dN.row(a).transpose() * pt.dV;
  if (what == Q1P0Output::ResidualAndTangent) {
    Eigen::Matrix<double, 9, 24> AB; // (A B)(iJ, 3b+k) = sum_L A(iJ, kL) dN_b/dX_L
    for (int b = 0; b < 8; ++b)
      for (int k = 0; k < 3; ++k) AB.col(3 * b + k).noalias() = A.middleCols<3>(3 * k) * dN.row(b).transpose();
    if (blocks == TangentBlocks::all) {
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i)
          tangent.row(3 * a + i).noalias() += pt.dV * dN.row(a) * AB.middleRows<3>(3 * i);
    } else {
      addUpperRows<0>(tangent, AB, dN, pt.dV);
    }
  }
  cauchyIntegral += P * pt.F.transpose() * pt.dV; // int sigma dv = int P F^T dV
}

// A hyperelastic law's A = d2W/dF2 is symmetric, but its entries are sums formed in different
// orders, so A and A^T differ in the last bits. Mirroring its upper blocks moves K by that much
// (1e-16 of it); a law unsymmetric by design differs by far more than 1e-10 of its largest entry.
bool symmetricToRoundOff(const Tangent9 &A) {
  const double scale = A.cwiseAbs().maxCoeff();
  for (int r = 1; r < 9; ++r)
    for (int c = 0; c < r; ++c)
      if (std::abs(A(r, c) - A(c, r)) > 1e-10 * scale) return false;
  return true;
}

// K_ab = K_ba^T for b < a, from the upper blocks TangentBlocks::upper filled.
void mirrorUpperBlocks(ElementMatrix &tangent) {
  for (int a = 1; a < 8; ++a)
    for (int b = 0; b < a; ++b) tangent.block<3, 3>(3 * a, 3 * b) = tangent.block<3, 3>(3 * b, 3 * a).transpose();
}

} // namespace

ElementVector flattenNodes(const NodeMatrix &u) {
  ElementVector v;
  for (int a = 0; a < 8; ++a) v.segment<3>(3 * a) = u.row(a).transpose();
  return v;
}

namespace {
// The points' spatial gradients flattened (column q: n(3a+i) = n_a,i = (F^{-T} dN_a/dX)_i) and
// their weights J dV: the volume's gradient is their weighted sum, its Hessian their weighted
// products (evaluateDisplacementPart).
struct SpatialGradients {
  Eigen::Matrix<double, 24, 8> n;
  Eigen::Matrix<double, 8, 1> weight;
};

// V = int dV, v = int J dV and g_a = dv/du_a = int J F^{-T} dN_a/dX dV = sum_q w_q n_a(q).
SpatialGradients volumeAndGradient(const std::array<PointKinematics, 8> &pts, double &V, double &v, ElementVector &g) {
  SpatialGradients s;
  V = 0.0;
  for (int q = 0; q < 8; ++q) {
    const PointKinematics &pt = pts[q];
    V += pt.dV;
    s.weight(q) = pt.J * pt.dV;
    for (int a = 0; a < 8; ++a) s.n.block<3, 1>(3 * a, q).noalias() = pt.Finv.transpose() * pt.dNdX.row(a).transpose();
  }
  v = s.weight.sum();
  g.noalias() = s.n * s.weight;
  return s;
}

} // namespace

namespace {
// The Newton update of (theta, p) from iterate `base` to displacement u (see the header).
void extrapolateState(const MixedBase &base, const NodeMatrix &u, double V,
                      const materials::VolumetricEnergy &volumetric, double lambda, double &theta, double &p) {
  theta = (base.v + base.g.dot(flattenNodes(u - base.u))) / V;
  p = volumetric.dU(base.theta) + volumetric.d2U(base.theta) * (theta - base.theta) + lambda;
}
} // namespace

MixedBase mixedBase(const NodeMatrix &X, const NodeMatrix &u, const MixedBase *previous,
                    const materials::VolumetricEnergy &volumetric, double lambda) {
  MixedBase b;
  std::array<PointKinematics, 8> pts;
  double minJ = 0.0, V = 0.0;
  b.u = u;
  if (!kinematics(X, u, pts, minJ) || !(minJ > 0.0)) return b;
  volumeAndGradient(pts, V, b.v, b.g);
  if (previous && previous->valid) {
    extrapolateState(*previous, u, V, volumetric, lambda, b.theta, b.pressure);
  } else {
    b.theta = b.v / V;
    b.pressure = volumetric.dU(b.theta) + lambda;
  }
  b.valid = b.theta > 0.0;
  return b;
}

void evaluateDisplacementPart(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                              Q1P0Output what, Q1P0DisplacementPart &part) {
  // Reset in place: the part is the caller's kept slot, too large to build and copy per element.
  part.valid = part.lawFailed = part.withTangent = false;
  part.minJ = 1.0;
  part.referenceVolume = part.volume = part.energy = 0.0;
  part.residual.setZero();
  part.cauchyIntegral.setZero();
  const bool withTangent = what == Q1P0Output::ResidualAndTangent;
  if (withTangent) part.tangent.setZero();
  std::array<PointKinematics, 8> pts;
  if (!kinematics(X, u, pts, part.minJ) || !(part.minJ > 0.0)) return;
  part.valid = true;
  const SpatialGradients spatial = volumeAndGradient(pts, part.referenceVolume, part.volume, part.volumeGradient);
  materials::PointResponse iso;
  // Upper blocks while every point's A so far is symmetric (a hyperelastic law's is, to its
  // round-off); a point whose A is not (the eq. 5 fibre stress form) completes the blocks so far
  // and the rest of the element adds all of its blocks.
  TangentBlocks blocks = TangentBlocks::upper;
  for (int q = 0; q < 8; ++q) {
    const PointKinematics &pt = pts[q];
    if (!law.evaluate(q, pt.F, iso)) {
      part.lawFailed = true;
      return;
    }
    if (withTangent && blocks == TangentBlocks::upper && !symmetricToRoundOff(iso.dPdF)) {
      mirrorUpperBlocks(part.tangent);
      blocks = TangentBlocks::all;
    }
    addPoint(part.residual, part.tangent, part.cauchyIntegral, pt, iso.P, iso.dPdF, what, blocks);
    part.energy += iso.energy * pt.dV;
  }
  if (withTangent) {
    if (blocks == TangentBlocks::upper) mirrorUpperBlocks(part.tangent);
    // The volume's Hessian (d(J F^{-T})/dF contracted with B on both sides): with S = sum_q w_q n
    // n^T, its block (a, b) is S_ab - S_ab^T. S as one 24x8 product, 0.7x the time of eight
    // symmetric rank-1 updates.
    const Eigen::Matrix<double, 24, 8> weighted = spatial.n * spatial.weight.asDiagonal();
    ElementMatrix S;
    S.noalias() = weighted.lazyProduct(spatial.n.transpose());
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        const auto Sab = S.block<3, 3>(3 * a, 3 * b);
        part.volumeHessian.block<3, 3>(3 * a, 3 * b) = Sab - Sab.transpose();
      }
  }
  part.withTangent = withTangent;
}

namespace {
// R = R_iso + p g and K = K_iso + p d2v/du2 (+ the caller's volumetric term), the energy's
// isochoric part and the mean Cauchy stress (int sigma dv = int P_iso F^T dV + p v I).
void addPressure(const Q1P0DisplacementPart &part, double p, Q1P0Output what, Q1P0Result &r) {
  if (what == Q1P0Output::ResidualAndTangent && !part.withTangent)
    throw std::logic_error("finishQ1P0: the tangent of a displacement part formed without it");
  r.residual = part.residual + p * part.volumeGradient;
  if (what == Q1P0Output::ResidualAndTangent) r.tangent = part.tangent + p * part.volumeHessian;
  r.energy = part.energy;
  r.cauchyMean = (part.cauchyIntegral + p * part.volume * Eigen::Matrix3d::Identity()) / part.volume;
}
} // namespace

Q1P0Result finishQ1P0Mixed(const Q1P0DisplacementPart &part, const NodeMatrix &u, const MixedBase &base,
                           const materials::VolumetricEnergy &volumetric, double lambda, bool extrapolate,
                           Q1P0Output what) {
  Q1P0Result r;
  if (!base.valid) return r;
  r.minJ = part.minJ;
  if (!part.valid) return r;
  const double V = part.referenceVolume, v = part.volume;
  const ElementVector &g = part.volumeGradient;
  r.volumeGradient = g;
  double theta = base.theta, p = base.pressure;
  if (extrapolate) extrapolateState(base, u, V, volumetric, lambda, theta, p);
  if (!(theta > 0.0)) return r;
  r.referenceVolume = V;
  r.theta = theta;
  r.pressure = p;
  if (part.lawFailed) {
    r.lawFailed = true;
    return r;
  }
  addPressure(part, p, what, r);
  const double Rp = v - theta * V;
  const double Rtheta = V * (volumetric.dU(theta) - p + lambda);
  const double d2U = volumetric.d2U(theta);
  r.residual += g * ((d2U * Rp + Rtheta) / V);
  if (what == Q1P0Output::ResidualAndTangent) r.tangent.noalias() += (d2U / V) * g * g.transpose();
  r.energy += V * (volumetric.energy(theta) + lambda * (theta - 1.0)) + p * Rp;
  r.forceScale = std::hypot(r.residual.norm(), volumetric.d2U(theta) * std::cbrt(V * V));
  r.valid = true;
  return r;
}

Q1P0Result evaluateQ1P0Mixed(const NodeMatrix &X, const NodeMatrix &u, const MixedBase &base,
                             const QuadraturePointLaw &law, const materials::VolumetricEnergy &volumetric,
                             double lambda, bool extrapolate, Q1P0Output what) {
  if (!base.valid) return Q1P0Result{};
  return finishQ1P0Mixed(evaluateDisplacementPart(X, u, law, what), u, base, volumetric, lambda, extrapolate, what);
}

Q1P0Result finishQ1P0(const Q1P0DisplacementPart &part, const materials::VolumetricEnergy &volumetric, double lambda,
                      Q1P0Output what) {
  Q1P0Result r;
  r.minJ = part.minJ;
  if (!part.valid) return r;
  // Condensed dilatation: theta = v / V, and g_a = int J F^{-T} dN_a/dX dV = d v / d u_a.
  const double V = part.referenceVolume;
  const ElementVector &g = part.volumeGradient;
  r.volumeGradient = g;
  r.referenceVolume = V;
  r.theta = part.volume / V;
  r.pressure = volumetric.dU(r.theta) + lambda;
  if (part.lawFailed) {
    r.lawFailed = true;
    return r;
  }
  addPressure(part, r.pressure, what, r);
  if (what == Q1P0Output::ResidualAndTangent)
    r.tangent.noalias() += (volumetric.d2U(r.theta) / V) * g * g.transpose();
  r.energy += V * (volumetric.energy(r.theta) + lambda * (r.theta - 1.0));
  // The pressure's nodal forces p g cancel against the deviatoric ones in the residual, so their
  // size belongs in the round-off scale too: with the mixed method (kappa = 0 here, the pressure
  // an unknown) the residual of a uniform active state is otherwise below its own round-off and
  // Newton never stops (the isometric block at full activation, doc/incompressibility.md).
  r.forceScale = std::hypot(std::hypot(r.residual.norm(), volumetric.d2U(r.theta) * std::cbrt(V * V)),
                            r.pressure * g.norm());
  r.valid = true;
  return r;
}

Q1P0Result evaluateQ1P0(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                        const materials::VolumetricEnergy &volumetric, double lambda, Q1P0Output what) {
  return finishQ1P0(evaluateDisplacementPart(X, u, law, what), volumetric, lambda, what);
}

Q1P0Result evaluatePlainQ1(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                           const materials::VolumetricEnergy &volumetric, Q1P0Output what) {
  Q1P0Result r;
  std::array<PointKinematics, 8> pts;
  if (!kinematics(X, u, pts, r.minJ) || !(r.minJ > 0.0)) return r;
  double V = 0.0, v = 0.0, pressureIntegral = 0.0;
  materials::PointResponse iso;
  for (int q = 0; q < 8; ++q) {
    const PointKinematics &pt = pts[q];
    if (!law.evaluate(q, pt.F, iso)) {
      r.lawFailed = true;
      return r;
    }
    const Eigen::Matrix3d &Finv = pt.Finv;
    const Eigen::Matrix3d JFinvT = pt.J * Finv.transpose();
    const double p = volumetric.dU(pt.J);
    const Eigen::Matrix3d P = iso.P + p * JFinvT;
    Tangent9 A;
    if (what == Q1P0Output::ResidualAndTangent) {
      const auto c = flatten(JFinvT);
      A = iso.dPdF + p * cofactorDerivative(Finv, pt.J) + volumetric.d2U(pt.J) * c * c.transpose();
    }
    addPoint(r.residual, r.tangent, r.cauchyMean, pt, P, A, what);
    r.energy += (iso.energy + volumetric.energy(pt.J)) * pt.dV;
    V += pt.dV;
    v += pt.J * pt.dV;
    pressureIntegral += p * pt.J * pt.dV;
  }
  r.referenceVolume = V;
  r.theta = v / V;
  r.pressure = pressureIntegral / v;
  r.cauchyMean /= v;
  r.forceScale = std::hypot(r.residual.norm(), volumetric.d2U(r.theta) * std::cbrt(V * V));
  r.valid = true;
  return r;
}

bool elementVolumeGradient(const NodeMatrix &X, const NodeMatrix &u, double &V, double &v, ElementVector &g) {
  std::array<PointKinematics, 8> pts;
  double minJ = 0.0;
  if (!kinematics(X, u, pts, minJ) || !(minJ > 0.0)) return false;
  volumeAndGradient(pts, V, v, g);
  return true;
}

bool quadratureDeformationGradients(const NodeMatrix &X, const NodeMatrix &u, std::array<Eigen::Matrix3d, 8> &F,
                                    std::array<double, 8> &dV) {
  std::array<PointKinematics, 8> pts;
  double minJ = 0.0;
  if (!kinematics(X, u, pts, minJ)) return false;
  for (int q = 0; q < 8; ++q) {
    F[q] = pts[q].F;
    dV[q] = pts[q].dV;
  }
  return true;
}

} // namespace glossa::fem
