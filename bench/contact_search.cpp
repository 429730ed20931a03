// The cost of the contact search on the tongue against the palate: the AABB tree's build and
// one closest-point query per boundary node of the tongue (the nodes that can touch), on the
// coarse tongue and its uniform refinements, with no search radius and with a 5 mm one.
//
//   bench_contact_search [--repeats R] [--refines 0,1,2] [--out FILE]
//
// Run from the source root (it reads inputs/tongue/). Prints and appends to FILE (default
// bench/results/contact_search.csv) per mesh and radius: triangles, boundary nodes, the medians
// over R repeats of the surface's reading, the tree's build and one pass over the nodes, the
// time per query and queries per second.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "contact/ObjReader.hpp"
#include "contact/TriangulatedObstacle.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/MeshRefinement.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
double medianSeconds(int repeats, F &&f) {
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return median(seconds);
}

std::vector<Eigen::Vector3d> boundaryNodes(const glossa::mesh::HexMesh &mesh) {
  std::set<glossa::mesh::NodeId> ids;
  for (const auto &face : glossa::mesh::boundaryFaces(mesh)) {
    for (int a : glossa::mesh::kHexFaceNodes[face.localFace]) ids.insert(mesh.elements[face.element][a]);
  }
  std::vector<Eigen::Vector3d> x;
  for (auto n : ids) x.push_back(mesh.nodes[n]);
  return x;
}

}  // namespace

int main(int argc, char **argv) {
  using namespace glossa;
  int repeats = 7;
  std::vector<int> refines = {0, 1, 2};
  std::string out = "bench/results/contact_search.csv";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--repeats" && k + 1 < argc) {
      repeats = std::stoi(argv[++k]);
    } else if (a == "--refines" && k + 1 < argc) {
      refines.clear();
      std::istringstream list(argv[++k]);
      for (std::string r; std::getline(list, r, ',');) refines.push_back(std::stoi(r));
    } else if (a == "--out" && k + 1 < argc) {
      out = argv[++k];
    } else {
      std::cout << "usage: bench_contact_search [--repeats R] [--refines 0,1,2] [--out FILE]\n"
                   "the AABB tree's build and one closest-point query per tongue boundary node against "
                   "palate8.obj\n";
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const std::string dir = "inputs/tongue/";
  const std::string surfaceFile = dir + "palate8.obj";
  const double readSeconds = medianSeconds(repeats, [&] { contact::readObj(surfaceFile); });
  const contact::TriangleSurface palate = contact::readObj(surfaceFile);
  const double buildSeconds = medianSeconds(repeats, [&] { contact::TriangulatedObstacle tree(palate); });
  const contact::TriangulatedObstacle tree(palate);
  const mesh::HexMesh coarse = mesh::readAnsysMesh(dir + "tongue.node", dir + "tongue.elem").mesh;

  const bool fresh = !std::ifstream(out).good();
  std::ofstream csv(out, std::ios::app);
  if (fresh) {
    csv << "surface,triangles,refine,elements,boundary_nodes,search_radius_m,repeats,read_ms,tree_build_ms,"
           "all_nodes_ms,query_us,queries_per_s,found\n";
  }
  for (int refine : refines) {
    const mesh::HexMesh m = refine == 0 ? coarse : mesh::refineUniformly(coarse, refine);
    const std::vector<Eigen::Vector3d> nodes = boundaryNodes(m);
    for (double radius : {std::numeric_limits<double>::infinity(), 5e-3}) {
      std::size_t found = 0;
      const double pass = medianSeconds(repeats, [&] {
        found = 0;
        for (const auto &x : nodes) found += tree.closest(x, radius).has_value() ? 1 : 0;
      });
      const double perQuery = pass / static_cast<double>(nodes.size());
      std::ostringstream row;
      row << "palate8.obj," << palate.numTriangles() << "," << refine << "," << m.elements.size() << ","
          << nodes.size() << "," << (std::isinf(radius) ? std::string("inf") : std::to_string(radius)) << ","
          << repeats << "," << 1e3 * readSeconds << "," << 1e3 * buildSeconds << "," << 1e3 * pass << ","
          << 1e6 * perQuery << "," << 1.0 / perQuery << "," << found;
      std::cout << row.str() << "\n";
      csv << row.str() << "\n";
    }
  }
  return 0;
}
