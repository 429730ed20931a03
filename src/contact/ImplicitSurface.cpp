#include "contact/ImplicitSurface.hpp"

#include <cmath>

namespace glossa::contact {

double meanEdgeLength(const TriangleSurface &surface) {
  double sum = 0.0;
  for (std::size_t t = 0; t < surface.numTriangles(); ++t)
    for (int k = 0; k < 3; ++k) sum += (surface.corner(t, (k + 1) % 3) - surface.corner(t, k)).norm();
  return sum / (3.0 * static_cast<double>(surface.numTriangles()));
}

std::vector<Eigen::Vector3d> unitVertexNormals(const TriangleSurface &surface) {
  std::vector<Eigen::Vector3d> normals;
  normals.reserve(surface.vertices().size());
  for (std::size_t v = 0; v < surface.vertices().size(); ++v) normals.push_back(surface.vertexPseudonormal(v).normalized());
  return normals;
}

std::optional<ClosestPoint> implicitSurfaceAt(const std::vector<Eigen::Vector3d> &vertices,
                                              const std::vector<Eigen::Vector3d> &unitNormals,
                                              const std::vector<int> &neighbours, const Eigen::Vector3d &x,
                                              double radius) {
  // Sums of w, w h (h_i = N_i . (x - v_i)) and their first and second derivatives.
  double W = 0.0, S = 0.0;
  Eigen::Vector3d dW = Eigen::Vector3d::Zero(), dS = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ddW = Eigen::Matrix3d::Zero(), ddS = Eigen::Matrix3d::Zero();
  const double R2 = radius * radius;
  for (const int i : neighbours) {
    const Eigen::Vector3d d = x - vertices[static_cast<std::size_t>(i)];
    const double r = d.norm();
    const double s = r / radius;
    if (s >= 1.0) continue;
    const Eigen::Vector3d &N = unitNormals[static_cast<std::size_t>(i)];
    const double h = N.dot(d);
    const double a = 1.0 - s;
    // phi = a^4 (4 s + 1); grad phi = -20 a^3 d / R^2;
    // Hessian = -20 / R^2 (a^3 I - 3 a^2 d d^T / (R r)), the last term 0 at r = 0.
    const double w = a * a * a * a * (4.0 * s + 1.0);
    const Eigen::Vector3d dw = -20.0 * a * a * a / R2 * d;
    Eigen::Matrix3d ddw = -20.0 * a * a * a / R2 * Eigen::Matrix3d::Identity();
    if (r > 0.0) ddw += 60.0 * a * a / (R2 * radius * r) * d * d.transpose();
    W += w;
    S += w * h;
    dW += dw;
    dS += dw * h + w * N;
    ddW += ddw;
    ddS += ddw * h + dw * N.transpose() + N * dw.transpose();
  }
  if (!(W >= kSmallestWeightSum)) return std::nullopt;
  const double f = S / W;
  const Eigen::Vector3d g = (dS - f * dW) / W;
  // From f W = S twice differentiated.
  const Eigen::Matrix3d H = (ddS - g * dW.transpose() - dW * g.transpose() - f * ddW) / W;
  const double length = g.norm();
  if (!(length > 1e-8)) return std::nullopt;
  ClosestPoint cp;
  cp.normal = g / length;
  cp.gap = f;
  cp.point = x - f * cp.normal;
  cp.dGap = g;
  cp.dNormal = (Eigen::Matrix3d::Identity() - cp.normal * cp.normal.transpose()) * H / length;
  return cp;
}

}  // namespace glossa::contact
