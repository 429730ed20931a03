// Rigid motions and moving obstacles: the rotation order and pivot of RigidMotion by hand, and a
// triangulated cube moved and turned in time against the closed-form signed distance of the
// moved box (gap and normal), with dNormal against central differences in the moved frame.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "ContactTestSurfaces.hpp"
#include "contact/MovingObstacle.hpp"
#include "contact/TriangulatedObstacle.hpp"

namespace {

using glossa::contact::AxisRotation;
using glossa::contact::MovingObstacle;
using glossa::contact::RigidMotion;
using glossa::contact::TriangulatedObstacle;
namespace ct = glossa::contact::testing;

TEST(RigidMotion, RotationsApplyInOrderAboutThePivot) {
  const auto quarter = [](double) { return M_PI / 2; };
  const RigidMotion xThenZ({}, {AxisRotation{{1, 0, 0}, quarter}, AxisRotation{{0, 0, 2}, quarter}});
  const auto pose = xThenZ.at(0.0);
  EXPECT_LT((pose.toWorld({0, 1, 0}) - Eigen::Vector3d(0, 0, 1)).norm(),
            1e-15);  // x turns e_y to e_z, z keeps it
  EXPECT_LT((pose.toWorld({1, 0, 0}) - Eigen::Vector3d(0, 1, 0)).norm(),
            1e-15);  // x keeps e_x, z turns it to e_y
  const RigidMotion halfTurn({}, {AxisRotation{{0, 0, 1}, [](double t) { return M_PI * t; }}}, {1, 0, 0});
  EXPECT_LT((halfTurn.at(1.0).toWorld({0, 0, 0}) - Eigen::Vector3d(2, 0, 0)).norm(), 1e-15);
  EXPECT_LT((halfTurn.at(0.5).toWorld({0, 0, 0}) - Eigen::Vector3d(1, -1, 0)).norm(), 1e-15);
  const RigidMotion slide({[](double t) { return 2 * t; }, {}, [](double t) { return -t; }}, {});
  EXPECT_EQ(slide.at(0.25).toWorld({1, 1, 1}), Eigen::Vector3d(1.5, 1, 0.75));
  const auto p = halfTurn.at(0.3);
  EXPECT_LT((p.toBody(p.toWorld({0.2, -0.4, 0.9})) - Eigen::Vector3d(0.2, -0.4, 0.9)).norm(), 1e-15);
  EXPECT_THROW(RigidMotion({}, {AxisRotation{{0, 0, 0}, quarter}}), std::invalid_argument);
}

// The unit cube turned by theta(t) = pi/6 t about z through its centre and moved by
// c(t) = (0.5 t, 0, 0.2 t).
MovingObstacle movingCube() {
  return MovingObstacle(
      std::make_shared<TriangulatedObstacle>(ct::unitCube()),
      RigidMotion({[](double t) { return 0.5 * t; }, {}, [](double t) { return 0.2 * t; }},
                  {AxisRotation{{0, 0, 1}, [](double t) { return M_PI / 6 * t; }}}, {0.5, 0.5, 0.5}));
}

TEST(MovingObstacle, MovedCubeGivesTheGapAndNormalOfTheMovedBox) {
  MovingObstacle cube = movingCube();
  cube.setTime(1.0);
  // The moved box written out: centre and axes at t = 1 (30 degrees).
  const Eigen::Vector3d centre(1.0, 0.5, 0.7);
  Eigen::Matrix3d axes;
  axes.col(0) << std::sqrt(3.0) / 2, 0.5, 0;
  axes.col(1) << -0.5, std::sqrt(3.0) / 2, 0;
  axes.col(2) << 0, 0, 1;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  int inside = 0;
  for (int k = 0; k < 400; ++k) {
    const Eigen::Vector3d x = centre + Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d xi = axes.transpose() * (x - centre);
    const Eigen::Vector3d q = xi.cwiseAbs().array() - 0.5;  // the box's signed distance
    const Eigen::Vector3d out = q.cwiseMax(0.0);
    const double sdf = out.norm() > 0 ? out.norm() : q.maxCoeff();
    const auto cp = cube.closest(x, 10.0);
    ASSERT_TRUE(cp.has_value());
    EXPECT_NEAR(cp->gap, sdf, 1e-14) << "at " << x.transpose();
    Eigen::Vector3d gradient;
    if (out.norm() > 0) {
      gradient = axes * out.cwiseProduct(xi.cwiseSign()).normalized();
    } else {
      ++inside;
      int i;
      q.maxCoeff(&i);
      Eigen::Vector3d sorted = q;
      std::sort(sorted.data(), sorted.data() + 3);
      if (sorted[2] - sorted[1] < 1e-6) continue;  // two faces equally near: either normal
      gradient = axes.col(i) * (xi[i] > 0 ? 1.0 : -1.0);
    }
    EXPECT_LT((cp->normal - gradient).norm(), 1e-12) << "at " << x.transpose();
  }
  EXPECT_GT(inside, 10);
}

TEST(MovingObstacle, DNormalIsTheRotatedOneAsFiniteDifferencesSay) {
  MovingObstacle cube = movingCube();
  cube.setTime(0.7);
  const auto normal = [&](const Eigen::Vector3d &y) { return cube.closest(y, 10.0)->normal; };
  // Beyond the corner X = (1, 1, 1), and beyond the edge X = (1, 1, z), in the moved frame.
  for (const Eigen::Vector3d &X : {Eigen::Vector3d(1.3, 1.2, 1.4), Eigen::Vector3d(1.3, 1.2, 0.6)}) {
    const Eigen::Vector3d x = cube.pose().toWorld(X);
    const auto cp = cube.closest(x, 10.0);
    ASSERT_TRUE(cp.has_value());
    EXPECT_GT(cp->dNormal.norm(), 1.0);
    EXPECT_LT((cp->dNormal - ct::centralDifference(normal, x, 1e-6)).norm(), 1e-8);
  }
}

TEST(MovingObstacle, AtTimeZeroWithoutMotionItIsTheObstacleItself) {
  const auto fixed = std::make_shared<TriangulatedObstacle>(ct::octahedron());
  const MovingObstacle still(fixed, RigidMotion());
  const Eigen::Vector3d x(0.4, -0.7, 0.9);
  EXPECT_EQ(still.closest(x, 10.0)->gap, fixed->closest(x, 10.0)->gap);
  EXPECT_FALSE(still.closest(x, 0.01).has_value());
}

}  // namespace
