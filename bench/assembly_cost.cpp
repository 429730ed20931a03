// One assembly (residual and tangent) of a deck's mesh against the element work it contains: the
// same kernels with the same point laws over the same elements, nothing gathered (the
// target: assembly per element within 1.5x of the kernel plus its point laws). The state is a smooth
// shear, u = (0, s (x - x_min), 0) with s = 0.02, so that every point law (and every Hill fibre's local
// contractile solve) does its real work.
//
//   bench_assembly_cost [--repeats R] [--out FILE] [--lift DZ] [--contact NAME] DECK [DECK ...]
//
// Prints and appends to FILE (default bench/results/assembly_cost.csv) per deck: elements, the
// median over R repeats of one assembly and of its element work, per element, and their ratio.
// A deck with contacts is also assembled without them (the same scene, its Contact section
// dropped), the two in turn: contact_share is (with - without) / without of the fastest repeats,
// the cost of the search and the contact assembly against the rest of an assembly. --lift adds a
// rigid lift DZ [m] along +z to the state, so that a body below an obstacle (the tongue under the
// palate) is pressed into it and its contact points are active, not only searched. --contact
// keeps only the deck's contact of that name (one obstacle's cost).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <memory>
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

// One scene's assembler at the sheared (and lifted) state: one assembly (residual and tangent) or
// its element work alone, on demand.
class Subject {
 public:
  Subject(const glossa::model::Scene &scene, const Teuchos::RCP<const Teuchos::Comm<int>> &comm, double lift,
          double time)
      : time_(time) {
    using namespace glossa;
    assembly::DofLayout layout = assembly::distributeScene(scene, comm);
    history_ = std::make_unique<model::MuscleHistory>(scene.muscles, layout.localElements);
    // Every pass here is at the same state: kept displacement parts would measure their reuse,
    // not the element work.
    assembler_ = std::make_unique<assembly::Assembler>(scene, std::move(layout), *history_, comm, nullptr,
                                                       assembly::ElementParts::Fresh);
    results_ = std::make_unique<assembly::ResultEvaluator>(*assembler_);
    K_ = assembler_->createMatrix();
    u_ = std::make_unique<assembly::Vector>(assembler_->layout().ownedMap());
    f_ = std::make_unique<assembly::Vector>(assembler_->layout().ownedMap());
    double xMin = 1e300;
    for (const auto &X : scene.mesh.nodes) xMin = std::min(xMin, X(0));
    std::vector<double> all(3 * scene.mesh.numNodes(), 0.0);
    for (std::size_t n = 0; n < scene.mesh.numNodes(); ++n) {
      all[3 * n + 1] = 0.02 * (scene.mesh.nodes[n](0) - xMin);
      all[3 * n + 2] = lift;
    }
    results_->scatterDisplacement(all, *u_);
    lambda_.assign(assembler_->layout().localElements.size(), 0.0);
    // One of each first: the scatter's offsets and the matrix's first fill are set-up, not assembly.
    assemble();
    elementWork();
  }
  void assemble() const { assembler_->assemble(*u_, time_, lambda_, nullptr, f_.get(), K_.get()); }
  void elementWork() const { results_->evaluateElementsOnly(*u_, lambda_); }

 private:
  double time_;
  std::unique_ptr<glossa::model::MuscleHistory> history_;
  std::unique_ptr<glossa::assembly::Assembler> assembler_;
  std::unique_ptr<glossa::assembly::ResultEvaluator> results_;
  decltype(assembler_->createMatrix()) K_;
  std::unique_ptr<glossa::assembly::Vector> u_, f_;
  std::vector<double> lambda_;
};

double seconds(const std::function<void()> &f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Cost {
  double assembly = 0.0;  // one assembly (residual and tangent), median [s]
  double work = 0.0;      // its element work alone, median [s]
  double fastest = 0.0;   // the fastest assembly: the least disturbed by other work on a shared machine [s]
  double fastestBare = 0.0;  // the same without the contacts [s]
};

// Assemblies of the scene with and without its contacts, taken in turn (so that a change of the
// machine's load falls on both alike), and the element work.
Cost measure(const glossa::model::Scene &scene, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
             int repeats, double lift, double time) {
  const Subject with(scene, comm, lift, time);
  glossa::model::Scene bare = scene;
  bare.contacts.clear();
  const Subject without(bare, comm, lift, time);
  std::vector<double> a, b, w;
  for (int r = 0; r < repeats; ++r) {
    a.push_back(seconds([&] { with.assemble(); }));
    b.push_back(seconds([&] { without.assemble(); }));
    w.push_back(seconds([&] { with.elementWork(); }));
  }
  return {median(a), median(w), *std::min_element(a.begin(), a.end()), *std::min_element(b.begin(), b.end())};
}
} // namespace

int main(int argc, char **argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  using namespace glossa;
  int repeats = 7;
  std::string out = "bench/results/assembly_cost.csv";
  double lift = 0.0;
  std::string only; // one contact of the deck to keep, the others dropped; empty: all
  std::vector<std::string> decks;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--repeats" && k + 1 < argc) repeats = std::stoi(argv[++k]);
    else if (a == "--out" && k + 1 < argc) out = argv[++k];
    else if (a == "--lift" && k + 1 < argc) lift = std::stod(argv[++k]);
    else if (a == "--contact" && k + 1 < argc) only = argv[++k];
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: bench_assembly_cost [--repeats R] [--out FILE] [--lift DZ] [--contact NAME] DECK [DECK ...]\n"
                   "one assembly (residual and tangent) against its element work alone, per element;\n"
                   "with contacts, also against the same assembly without them\n";
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
             "element_work_us_per_element,ratio,lift_m,contacts,fastest_assembly_ms,fastest_without_contact_"
             "ms,"
             "contact_share\n";
  }
  const Teuchos::ParameterList schema = app::deckSchema();
  for (const std::string &path : decks) {
    io::Deck deck = io::Deck::fromFile(path);
    deck.validate(schema);
    model::Scene scene = input::buildScene(deck, deck.root().sublist("Time").get<double>("end time"));
    if (!only.empty())
      scene.contacts.erase(std::remove_if(scene.contacts.begin(), scene.contacts.end(),
                                          [&](const model::RigidContact &c) { return c.name != only; }),
                           scene.contacts.end());
    const double time = 0.5 * deck.root().sublist("Time").get<double>("end time");
    const Cost c = measure(scene, comm, repeats, lift, time);
    // From the fastest repeats: the contacts' cost is a few per cent, below the spread of the
    // medians on a loaded machine.
    const double without = c.fastestBare;
    const double share = (c.fastest - without) / without;
    const double elements = static_cast<double>(scene.mesh.numElements());
    const int ranks = comm->getSize();
    const std::string label = only.empty() ? path : path + " (contact " + only + ")";
    if (root) {
      // Per element of the whole mesh: with several ranks, the wall time of the slowest rank's share.
      std::cout << std::fixed << std::setprecision(3) << label << ": " << elements << " elements, assembly "
                << 1e3 * c.assembly << " ms, element work " << 1e3 * c.work << " ms, ratio "
                << c.assembly / c.work;
      if (!scene.contacts.empty())
        std::cout << "; fastest " << 1e3 * c.fastest << " ms, without its " << scene.contacts.size()
                  << " contacts " << 1e3 * without << " ms: contact share " << share;
      std::cout << "\n";
      csv << label << "," << ranks << "," << elements << "," << repeats << "," << 1e3 * c.assembly << ","
          << 1e3 * c.work << "," << 1e6 * c.assembly * ranks / elements << ","
          << 1e6 * c.work * ranks / elements << "," << c.assembly / c.work << "," << lift << ","
          << scene.contacts.size() << "," << 1e3 * c.fastest << "," << 1e3 * without << "," << share << "\n";
    }
  }
  return 0;
}
