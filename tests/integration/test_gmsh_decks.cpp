// One deck on meshes of the same 2 x 1 x 3 mm block from four sources: the gmsh binary's MSH 2.2
// binary, MSH 4.1 ASCII and Abaqus .inp exports of one .geo, and Glossa's own box generator.
// Clamped at its base and sheared on its top, the block's top corner must move the same in
// all four runs: the imports feed the solver the same geometry, connectivity and face sets
// (the generator numbers nodes and elements its own way, so it checks that numbering does not
// matter). Skipped when gmsh was not found at configure time.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "RunDeck.hpp"

using namespace glossa;

namespace {

// 4 x 2 quadrangles extruded in 3 layers: the generator's box with cells {4, 2, 3}.
const char *kGeo = R"(SetFactory("Built-in");
Point(1) = {0,0,0}; Point(2) = {2e-3,0,0}; Point(3) = {2e-3,1e-3,0}; Point(4) = {0,1e-3,0};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
Transfinite Curve{1,3} = 5; Transfinite Curve{2,4} = 3; Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0,0,3e-3} { Surface{1}; Layers{3}; Recombine; };
Physical Volume("tissue") = {out[1]};
Physical Surface("base") = {1};
Physical Surface("top") = {out[0]};
)";

std::string deck(const std::string &mesh, const std::string &base, const std::string &top) {
  return R"x(<ParameterList name="Glossa">
  <ParameterList name="Mesh">)x" +
         mesh + R"x(
  </ParameterList>
  <ParameterList name="Material">
    <Parameter name="type" type="string" value="neo-Hookean"/>
    <Parameter name="shear modulus" type="double" value="1000"/>
  </ParameterList>
  <ParameterList name="Boundary conditions">
    <ParameterList name="clamped">
      <Parameter name="node set" type="string" value=")x" +
         base + R"x("/>
      <Parameter name="components" type="string" value="x,y,z"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Loads">
    <ParameterList name="shear">
      <Parameter name="face set" type="string" value=")x" +
         top + R"x("/>
      <Parameter name="traction" type="Array(double)" value="{100, 40, -50}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Named points">
    <ParameterList name="corner">
      <Parameter name="position" type="Array(double)" value="{2e-3, 1e-3, 3e-3}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Time">
    <Parameter name="end time" type="double" value="1"/>
    <Parameter name="step size" type="double" value="0.5"/>
  </ParameterList>
</ParameterList>
)x";
}

std::string fileMesh(const std::string &path) {
  return R"x(
    <Parameter name="type" type="string" value="file"/>
    <ParameterList name="File">
      <Parameter name="path" type="string" value=")x" +
         path + R"x("/>
    </ParameterList>)x";
}

std::vector<double> cornerDisplacement(const std::filesystem::path &dir, const std::string &name,
                                       const std::string &xml) {
  const std::filesystem::path file = dir / (name + ".xml");
  std::ofstream(file) << xml;
  // Exact Newton steps (a fresh factorisation at every iteration), so that each run converges far
  // below its tolerance and the meshes' numbering leaves round-off only: with the factors kept
  // (the default), inexact late steps stopped the runs 2e-9 of the displacement apart.
  const auto summary = test::runDeck(file.string(), {"Linear solver/direct reuse iterations=0"}, dir / ("out_" + name));
  EXPECT_TRUE(summary.at("converged").get<bool>()) << name;
  return summary.at("final_displacement").at("corner").get<std::vector<double>>();
}

TEST(GmshDecks, FourMeshSourcesMoveTheCornerAlike) {
  const std::string gmsh = GLOSSA_GMSH_EXECUTABLE;
  if (gmsh.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  const auto dir = test::scratchDirectory("gmsh_decks");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "block.geo") << kGeo;
  for (const auto &[name, options] :
       std::vector<std::pair<std::string, std::string>>{{"block22b.msh", "-format msh22 -bin"},
                                                        {"block41.msh", "-format msh41"},
                                                        {"block.inp", "-format inp"}}) {
    const std::string command = gmsh + " -3 " + (dir / "block.geo").string() + " " + options + " -o " +
                                (dir / name).string() + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  const auto generated = cornerDisplacement(dir, "generated",
                                            deck(R"x(
    <Parameter name="type" type="string" value="box"/>
    <ParameterList name="Box">
      <Parameter name="lengths" type="Array(double)" value="{2e-3, 1e-3, 3e-3}"/>
      <Parameter name="cells" type="Array(int)" value="{4, 2, 3}"/>
    </ParameterList>)x",
                                                 "zmin", "zmax"));
  // The shear moves the corner by a fair fraction of the block: a real, non-uniform solve.
  ASSERT_EQ(generated.size(), 3u);
  EXPECT_GT(generated[0], 1e-4);
  EXPECT_GT(generated[1], 1e-5);
  for (const std::string &name : std::vector<std::string>{"block22b.msh", "block41.msh", "block.inp"}) {
    SCOPED_TRACE(name);
    const auto u =
        cornerDisplacement(dir, name.substr(0, name.find('.')) + "_" + name.substr(name.find('.') + 1),
                           deck(fileMesh(name), "base", "top"));
    ASSERT_EQ(u.size(), 3u);
    // Newton converges each run to its tolerance; the numbering changes round-off only.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(u[k], generated[k], 1e-10 * std::abs(generated[0])) << k;
  }
}

}  // namespace
