// Fibre direction fields against directions computed by hand on a box mesh.
#include <fstream>

#include <gtest/gtest.h>

#include "fem/HexShape.hpp"
#include "mesh/BoxGenerator.hpp"
#include "model/FibreDirectionField.hpp"

using namespace glossa;

namespace {
// 2 x 1 x 1 elements on [0,2] x [0,1] x [0,1]: centroids (0.5, .5, .5) and (1.5, .5, .5).
mesh::HexMesh twoCells() { return mesh::generateBox({0, 0, 0}, {2, 1, 1}, {2, 1, 1}); }

std::filesystem::path writeFile(const std::string &name, const std::string &text) {
  const auto dir = std::filesystem::path(GLOSSA_BINARY_DIR) / "test-output" / "fibre_fields";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

void expectParallel(const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
  EXPECT_NEAR(a.norm(), 1.0, 1e-14);
  EXPECT_NEAR(std::abs(a.dot(b.normalized())), 1.0, 1e-14) << a.transpose() << " vs " << b.transpose();
}
} // namespace

TEST(FibreDirectionField, ConstantIsNormalisedAndRefusesZero) {
  const auto d = model::constantDirections({0, 3, 4}, 2);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_TRUE(d[1].isApprox(Eigen::Vector3d(0, 0.6, 0.8)));
  EXPECT_THROW(model::constantDirections(Eigen::Vector3d::Zero(), 1), std::invalid_argument);
}

TEST(FibreDirectionField, RadialFanPointsFromTheCentreToEachCentroid) {
  const auto m = twoCells();
  const auto d = model::radialFanDirections(m, {0, 1}, {1, 0.5, -1}, Eigen::Vector3d::Zero());
  expectParallel(d[0], Eigen::Vector3d(-0.5, 0, 1.5));
  expectParallel(d[1], Eigen::Vector3d(0.5, 0, 1.5));
  EXPECT_GT(d[0].z(), 0.0); // from the centre outwards
  // In the plane y = const the fan drops its y component.
  const auto p = model::radialFanDirections(m, {0, 1}, {1, -3, -1}, {0, 1, 0});
  expectParallel(p[1], Eigen::Vector3d(0.5, 0, 1.5));
  // A centroid on the centre has no direction.
  try {
    model::radialFanDirections(m, {0, 1}, {1.5, 0.5, 0.5}, Eigen::Vector3d::Zero());
    FAIL() << "expected an error";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("element 1"), std::string::npos) << e.what();
  }
}

TEST(FibreDirectionField, ElementFileWithCommentsAndCommas) {
  const auto m = twoCells();
  const auto f = writeFile("elements.txt", "# id nx ny nz\n0, 2, 0, 0\n\n1\t0 0 -5  # down\n");
  const auto d = model::directionsFromFile(f, model::DirectionsPer::Element, m, {0, 1});
  EXPECT_TRUE(d[0].isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(d[1].isApprox(-Eigen::Vector3d::UnitZ()));
}

TEST(FibreDirectionField, NodeFileAveragesAxiallyOverTheElement) {
  const auto m = twoCells();
  std::string text;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) // alternate signs: the same axial fibre
    text += std::to_string(n) + (n % 2 ? " -1 -1 0\n" : " 1 1 0\n");
  const auto d = model::directionsFromFile(writeFile("nodes.txt", text), model::DirectionsPer::Node, m, {0, 1});
  for (const auto &v : d) expectParallel(v, Eigen::Vector3d(1, 1, 0));
}

TEST(FibreDirectionField, FileErrorsNameFileAndLine) {
  const auto m = twoCells();
  auto message = [&](const std::string &text, model::DirectionsPer per = model::DirectionsPer::Element) {
    try {
      model::directionsFromFile(writeFile("bad.txt", text), per, m, {0, 1});
    } catch (const std::runtime_error &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("0 1 0 0\n1 1 0\n").find("bad.txt:2: expected 'id nx ny nz'"), std::string::npos);
  EXPECT_NE(message("0 1 0 0\n7 1 0 0\n").find("bad.txt:2: element id 7 is out of range [0, 1]"), std::string::npos);
  EXPECT_NE(message("0 1 0 0\n0 1 0 0\n").find("bad.txt:2: element 0 is given twice"), std::string::npos);
  EXPECT_NE(message("0 0 0 0\n").find("bad.txt:1: the direction of element 0 is zero"), std::string::npos);
  EXPECT_NE(message("0 1 0 0\n").find("no direction for element 1"), std::string::npos);
  EXPECT_NE(message("0 1 0 0\n", model::DirectionsPer::Node).find("no direction for node 1 of element 0"),
            std::string::npos);
  EXPECT_THROW(model::directionsFromFile("/nonexistent/fibres.txt", model::DirectionsPer::Element, m, {0}),
               std::runtime_error);
}

// Polylines: each element takes the direction of the segment nearest to its centroid, oriented
// from the segment's first vertex to its second.
TEST(FibreDirectionField, StraightPolylineGivesItsDirection) {
  const auto m = twoCells();
  // One straight fibre along (1, 2, 2)/3 through the box, in three segments, far from neither.
  const Eigen::Vector3d a(-1, -1, -1), d = Eigen::Vector3d(1, 2, 2) / 3.0;
  const model::Polylines lines{{a, a + 1.0 * d, a + 2.5 * d, a + 6.0 * d}};
  const auto N = model::polylineDirections(m, {0, 1}, lines);
  ASSERT_EQ(N.size(), 2u);
  for (const auto &n : N) EXPECT_LT((n - d).norm(), 1e-15) << n.transpose();
  // Reversing the vertex order reverses the direction (the documented sign convention).
  const model::Polylines reversed{{a + 6.0 * d, a + 2.5 * d, a + 1.0 * d, a}};
  EXPECT_LT((model::polylineDirections(m, {1}, reversed)[0] + d).norm(), 1e-15);
}

TEST(FibreDirectionField, NearestSegmentIsChosen) {
  // Two fibres: one along x at height z = 0, one along y at height z = 1 (an L-shaped polyline
  // in the plane z = 1 whose second leg runs along z).
  const model::Polylines lines{{{0, 0, 0}, {4, 0, 0}},
                               {{0, 0, 1}, {0, 4, 1}, {0, 4, 5}}};
  // Nearer the first fibre (distance 0.2 against 2.15).
  EXPECT_LT((model::nearestSegmentDirection(lines, {2, 0, 0.2}) - Eigen::Vector3d::UnitX()).norm(), 1e-15);
  // Nearer the second fibre's first segment (distance 0.14 against 2.19 and 2.0).
  EXPECT_LT((model::nearestSegmentDirection(lines, {0.1, 2, 0.9}) - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  // Past the end of the first leg: the distance is to the closed segment, so the vertical leg
  // (distance 0.5) wins over the first leg's end point (distance 1.58).
  EXPECT_LT((model::nearestSegmentDirection(lines, {0, 4.5, 2.5}) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  // Per element: the box's two centroids (0.5, .5, .5) and (1.5, .5, .5), with a fibre along z
  // through x = 1.6 and one along y at x = 0.4: each element takes the nearer one.
  const model::Polylines two{{{0.4, -1, 0.5}, {0.4, 2, 0.5}}, {{1.6, 0.5, -1}, {1.6, 0.5, 2}}};
  const auto N = model::polylineDirections(twoCells(), {0, 1}, two);
  EXPECT_LT((N[0] - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  EXPECT_LT((N[1] - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
}

TEST(FibreDirectionField, AVertexSharedByTwoSegmentsGoesToTheFirstWhateverTheRounding) {
  // A point beyond the shared vertex a1 of both segments (s = 1 on the first, s = 0 on the second):
  // the vertex is its nearest point on both, a tie the documented rule gives to the first segment.
  // a0 + 1 (a1 - a0) rounds to a point 1 ulp off a1 here, which made the second segment nearer by
  // 1e-16 and gave it the point (doc/materials.md, "In decks").
  const Eigen::Vector3d a0(0.5800356635322673, 0.7377223518974553, 0.36911421306560027),
      a1(-0.8772781329503792, 2.8858594384327594, 2.7714056273893544),
      a2(-1.5549088263423414, 3.3938675817365036, 3.2017074238642613),
      x(-0.7868908433359323, 2.907636278026478, 2.83928019129692);
  ASSERT_NE((a0 + 1.0 * (a1 - a0) - a1).norm(), 0.0);  // the rounding this test is about
  const Eigen::Vector3d first = (a1 - a0).normalized();
  EXPECT_LT((model::nearestSegmentDirection({{a0, a1, a2}}, x) - first).norm(), 1e-15);
}

TEST(FibreDirectionField, PolylinesWithoutASegmentAreRefused) {
  EXPECT_THROW(model::nearestSegmentDirection({}, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(model::nearestSegmentDirection({{{1, 1, 1}, {1, 1, 1}}}, Eigen::Vector3d::Zero()),
               std::invalid_argument);
  // A zero-length segment is skipped, not taken as a direction.
  const model::Polylines lines{{{0, 0, 0}, {0, 0, 0}, {0, 0, 3}}};
  EXPECT_LT((model::nearestSegmentDirection(lines, {0, 0, -1}) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
}

// Per quadrature point: each Gauss point takes the segment nearest to itself, so an element lying
// between two fibres carries both directions, each where it is nearer.
TEST(FibreDirectionField, PerQuadraturePointFollowsTheNearerFibre) {
  // Element 0 is the unit cube; a fibre along y on its face x = 0 (at z = 0.5) and one along z on
  // its face x = 1 (at y = 0.5). The Gauss points at x = 0.21 are 0.36 from the first fibre and
  // at least 0.79 from the second; those at x = 0.79 the other way round.
  const model::Polylines lines{{{0, -1, 0.5}, {0, 2, 0.5}}, {{1, 0.5, -1}, {1, 0.5, 2}}};
  const auto N = model::polylinePointDirections(twoCells(), {0}, lines);
  ASSERT_EQ(N.size(), 1u);
  const auto &points = fem::gaussHex2();
  for (int q = 0; q < 8; ++q) {
    const Eigen::Vector3d expected = points[q].xi.x() < 0 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
    EXPECT_LT((N[0][q] - expected).norm(), 1e-15) << "point " << q;
  }
  // A straight fibre gives its direction at every point of every element.
  const Eigen::Vector3d a(-1, -1, -1), d = Eigen::Vector3d(1, 2, 2) / 3.0;
  for (const auto &element : model::polylinePointDirections(twoCells(), {0, 1}, {{a, a + 6.0 * d}}))
    for (const auto &n : element) EXPECT_LT((n - d).norm(), 1e-15);
  EXPECT_THROW(model::polylinePointDirections(twoCells(), {0}, {}), std::invalid_argument);
}
