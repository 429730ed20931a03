// The reference coordinates file (Mesh/reference coordinates file, glossa zero-strain): a round
// trip is exact, and every malformed file is refused with its file and line.

#include <gtest/gtest.h>

#include "ImportTestSupport.hpp"
#include "mesh/ReferenceCoordinates.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;

TEST(ReferenceCoordinates, RoundTripIsExact) {
  testing::ScratchDir scratch("reference_coordinates");
  const std::vector<Eigen::Vector3d> nodes{
      {0.1, -2.5e-3, 1.0 / 3.0}, {1e-17, 0.0, -7.0}, {0.11355463004010322, 2, 3}};
  const std::string file = scratch.write("x.txt", "");
  writeReferenceCoordinates(file, nodes, {"a header line"});
  const auto read = readReferenceCoordinates(file, nodes.size());
  ASSERT_EQ(read.size(), nodes.size());
  for (std::size_t n = 0; n < nodes.size(); ++n)
    EXPECT_EQ(read[n], nodes[n]) << "node " << n;  // %.17g: bit-exact
}

TEST(ReferenceCoordinates, AnyOrderCommasAndComments) {
  testing::ScratchDir scratch("reference_coordinates");
  const std::string file = scratch.write("x.csv", "# node, x, y, z\n\n1, 4, 5, 6\n0\t1 2 3\r\n");
  const auto read = readReferenceCoordinates(file, 2);
  EXPECT_EQ(read[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(read[1], Eigen::Vector3d(4, 5, 6));
}

TEST(ReferenceCoordinates, MalformedFilesNameFileAndLine) {
  testing::ScratchDir scratch("reference_coordinates");
  auto bad = [&](const std::string &name, const std::string &text, std::size_t nodes,
                 const std::vector<std::string> &expected) {
    const std::string file = scratch.write(name, text);
    expectError([&] { readReferenceCoordinates(file, nodes); }, expected);
  };
  bad("short.txt", "0 1 2 3\n1 4 5\n", 2, {"short.txt:2:", "expected 'node x y z'"});
  bad("long.txt", "0 1 2 3 4\n", 1, {"long.txt:1:", "fifth field '4'"});
  bad("index.txt", "# c\nA 1 2 3\n", 1, {"index.txt:2:", "node index 'A' is not an integer"});
  bad("range.txt", "0 1 2 3\n2 1 2 3\n", 2, {"range.txt:2:", "node 2 is outside the mesh (0 to 1)"});
  bad("negative.txt", "-1 1 2 3\n", 2, {"negative.txt:1:", "outside the mesh"});
  bad("twice.txt", "0 1 2 3\n\n0 1 2 3\n", 2, {"twice.txt:3:", "node 0 is given twice (first on line 1)"});
  bad("number.txt", "0 1 2x 3\n", 1, {"number.txt:1:", "coordinate '2x' is not a finite number"});
  bad("nan.txt", "0 1 nan 3\n", 1, {"nan.txt:1:", "coordinate 'nan'"});
  bad("count.txt", "0 1 2 3\n", 3, {"count.txt:", "1 nodes, but the mesh has 3"});
  expectError([&] { readReferenceCoordinates(scratch.file("absent.txt"), 1); },
              {"absent.txt", "cannot open the reference coordinates file"});
}

}  // namespace
}  // namespace glossa::mesh
