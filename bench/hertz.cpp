// The Hertz study (doc/contact.md, "Hertz"): both inputs/verification/hertz_*.xml decks, with
// Gauss and nodal contact points, on meshes whose counts are the deck's times 0.25 to 2 (4 to 32
// cells of the fine band per Hertz half-width), measured as tests/integration/test_hertz.cpp
// measures them (HertzContact.hpp). One row per run in bench/results/hertz.csv.
//
//   cmake --build build --target bench_hertz && build/bench_hertz [--scales 0.25,0.5,1,2]
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "HertzContact.hpp"

using namespace glossa;

int main(int argc, char *argv[]) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  std::vector<double> scales = {0.25, 0.5, 1.0, 2.0};
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) != "--scales") {
      std::cerr << "usage: bench_hertz [--scales 0.25,0.5,1,2]\n";
      return 2;
    }
    scales.clear();
    std::stringstream list(argv[i + 1]);
    for (std::string item; std::getline(list, item, ',');) scales.push_back(std::stod(item));
  }
  const std::string file = std::string(GLOSSA_SOURCE_DIR) + "/bench/results/hertz.csv";
  std::ofstream csv(file);
  csv << "deck,rule,scale,elements,load_per_length [N/m],a_hertz [m],a [m],a_error [-],p0_hertz [Pa],p0 [Pa],"
         "p0_error [-],deviation [-],oscillation [-],loaded_nodes [-],a_over_R [-],strain [-],newton [-],uzawa [-],"
         "contact_updates [-],wall [s]\n";
  for (const char *deck : {"hertz_cylinder.xml", "hertz_cylinder_incompressible.xml"})
    for (const char *rule : {"gauss", "nodal"})
      for (double scale : scales) {
        // One layer of cells factors like a 2D mesh: MUMPS beats MueLu on these meshes at every size.
        const auto r = test::runHertz(test::inputPath(std::string("verification/") + deck), scale, rule,
                                      test::scratchDirectory("bench_hertz"), {"Linear solver/direct up to=1000000"});
        const double load = 0.5 * M_PI * r.hertz.p0 * r.hertz.a;
        csv << deck << ',' << rule << ',' << scale << ',' << r.elements << ',' << load << ',' << r.hertz.a << ','
            << r.measured.a << ',' << r.errorA() << ',' << r.hertz.p0 << ',' << r.measured.p0 << ',' << r.errorP0()
            << ',' << r.measured.deviation << ',' << r.measured.oscillation << ',' << r.measured.loadedNodes << ',' << r.hertz.a / r.radius
            << ',' << r.hertz.p0 / r.eStar << ',' << r.newton << ',' << r.uzawa << ',' << r.contactUpdates << ','
            << r.seconds << '\n'
            << std::flush;
        std::printf("%s %s x%.2f: a error %+.2f%%, p0 error %+.2f%%, %.0f s\n", deck, rule, scale, 100 * r.errorA(),
                    100 * r.errorP0(), r.seconds);
      }
  std::printf("wrote %s\n", file.c_str());
  return 0;
}
