// One assembly (residual and tangent) of a deck's mesh against the element work it contains: the
// same kernels with the same point laws over the same elements, nothing gathered (the
// target: assembly per element within 1.5x of the kernel plus its point laws). The state is a smooth
// shear, u = (0, s (x - x_min), 0) with s = 0.02, so that every point law (and every Hill fibre's local
// contractile solve) does its real work.
//
//   bench_assembly_cost [--repeats R] [--out FILE] DECK [DECK ...]
//
// Prints and appends to FILE (default bench/results/assembly_cost.csv) per deck: elements, the
// median over R repeats of one assembly and of its element work, per element, and their ratio.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "app/DeckSchema.hpp"
#include "assembly/Assembler.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "io/deck/Deck.hpp"
#include "input/SceneFactory.hpp"

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F> std::vector<double> timed(int repeats, F &&f) {
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return seconds;
}
} // namespace

int main(int argc, char **argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  using namespace glossa;
  int repeats = 7;
  std::string out = "bench/results/assembly_cost.csv";
  std::vector<std::string> decks;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--repeats" && k + 1 < argc) repeats = std::stoi(argv[++k]);
    else if (a == "--out" && k + 1 < argc) out = argv[++k];
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: bench_assembly_cost [--repeats R] [--out FILE] DECK [DECK ...]\n"
                   "one assembly (residual and tangent) against its element work alone, per element\n";
      return 0;
    } else decks.push_back(a);
  }
  const auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::ofstream csv;
  if (root) {
    const bool fresh = !std::ifstream(out).good();
    csv.open(out, std::ios::app);
    if (fresh)
      csv << "deck,ranks,elements,repeats,assembly_ms,element_work_ms,assembly_us_per_element,"
             "element_work_us_per_element,ratio\n";
  }
  const Teuchos::ParameterList schema = app::deckSchema();
  for (const std::string &path : decks) {
    io::Deck deck = io::Deck::fromFile(path);
    deck.validate(schema);
    const model::Scene scene = input::buildScene(deck, deck.root().sublist("Time").get<double>("end time"));
    assembly::DofLayout layout = assembly::distributeScene(scene, comm);
    const model::MuscleHistory history(scene.muscles, layout.localElements);
    const assembly::Assembler assembler(scene, std::move(layout), history, comm);
    const assembly::ResultEvaluator results(assembler); // the element work alone
    auto K = assembler.createMatrix();
    assembly::Vector u(assembler.layout().ownedMap()), f(assembler.layout().ownedMap());
    {
      double xMin = 1e300;
      for (const auto &X : scene.mesh.nodes) xMin = std::min(xMin, X(0));
      std::vector<double> all(3 * scene.mesh.numNodes(), 0.0);
      for (std::size_t n = 0; n < scene.mesh.numNodes(); ++n)
        all[3 * n + 1] = 0.02 * (scene.mesh.nodes[n](0) - xMin);
      results.scatterDisplacement(all, u);
    }
    const std::vector<double> lambda(assembler.layout().localElements.size(), 0.0);
    const double time = 0.5 * deck.root().sublist("Time").get<double>("end time");
    // One of each first: the scatter's offsets and the matrix's first fill are set-up, not assembly.
    assembler.assemble(u, time, lambda, nullptr, &f, K.get());
    results.evaluateElementsOnly(u, lambda);
    const double assembly = median(timed(repeats, [&] { assembler.assemble(u, time, lambda, nullptr, &f, K.get()); }));
    const double work = median(timed(repeats, [&] { results.evaluateElementsOnly(u, lambda); }));
    const double elements = static_cast<double>(scene.mesh.numElements());
    const int ranks = comm->getSize();
    if (root) {
      // Per element of the whole mesh: with several ranks, the wall time of the slowest rank's share.
      std::cout << std::fixed << std::setprecision(3) << path << ": " << elements << " elements, assembly "
                << 1e3 * assembly << " ms, element work " << 1e3 * work << " ms, ratio " << assembly / work << "\n";
      csv << path << "," << ranks << "," << elements << "," << repeats << "," << 1e3 * assembly << "," << 1e3 * work
          << "," << 1e6 * assembly * ranks / elements << "," << 1e6 * work * ranks / elements << "," << assembly / work
          << "\n";
    }
  }
  return 0;
}
