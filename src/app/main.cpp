// glossa: the command-line front end. `glossa --help` lists the commands.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include <mpi.h>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>

#include "app/CurvesCommand.hpp"
#include "app/DeckSchema.hpp"
#include "app/MeshCommand.hpp"
#include "app/PointCommand.hpp"
#include "app/SingletonSession.hpp"
#include "app/ZeroStrainCommand.hpp"
#include "io/deck/Deck.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/DeckReference.hpp"
#include "io/output/OutputError.hpp"
#include "mesh/MeshError.hpp"
#include "input/AirwayParameters.hpp"
#include "input/SceneFactory.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/parameters/RunChecks.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/RunSimulation.hpp"

namespace {

const char *kHeader = "glossa - finite elements for nearly incompressible, fibre-reinforced, active soft tissue\n";

// One entry per command: `glossa --help` prints them all, `glossa CMD --help` only CMD's.
struct CommandHelp {
  const char *command, *text;
};
const CommandHelp kCommands[] = {
    {"run", R"(  glossa run DECK.xml [--output DIR] [--set path/to/parameter=value ...] [--quiet | --verbose]
             [--timers] [--control-groups G] [--restart DIR]
      run a deck; results (results.xdmf/.h5, traces.csv, summary.json) go to DIR
      (default: the deck's Output/directory). Under mpiexec -np N it runs on N ranks.
      It prints a line per step (step k/N, time, iterations, elapsed and estimated time left);
      --verbose adds every Newton and Uzawa iteration (under a controller, every candidate
      solve: its value or why it failed, and its cost), --quiet prints only failures.
      --timers prints Trilinos' timers (MueLu set-up, Belos solve) at the end.
      --control-groups G splits the N ranks into G groups that solve the genetic
      algorithm's candidates concurrently, N/G ranks each (G must divide N).
      --restart DIR continues the run whose results are in DIR from its latest checkpoint
      (written every Output/checkpoint every steps and when the run is stopped by a signal),
      with the same deck and --set values and on as many ranks; its files end as an
      uninterrupted run's would.
)"},
    {"validate", R"(  glossa validate DECK.xml [--set path=value ...] [--print]
      check a deck (parameters, and the mesh sets and points it names) and say that it is
      valid; --print prints the deck with every default filled in (XML, on stdout)
)"},
    {"schema", R"(  glossa schema [--markdown]
      print every deck parameter (--markdown: the text of doc/deck-reference.md)
)"},
    {"point", R"(  glossa point DECK.xml [--output FILE] [--set path=value ...]
      drive one material point of the deck's Material along the deck's Point path
      (uniaxial, simple shear or a table of F) with its muscle groups' inputs; writes
      stress, fibre and contractile stretches, tensions and activations to FILE
      (default: point.csv)
)"},
    {"mesh",
     R"(  glossa mesh FILE [--format gmsh|abaqus|ansys] [--refine N] [--json] [--output DIR|OUT.msh|OUT.inp]
      read a mesh (Gmsh .msh 2.2/4.1 ASCII or binary, Abaqus .inp, ANSYS .node/.elem),
      optionally refine it, and print its counts, sets, volume and element quality
      (--output DIR: XDMF for ParaView; OUT.msh or OUT.inp: the mesh with all its sets; any
      other extension is refused: a directory named with a dot needs a trailing /)
)"},
    {"zero-strain",
     R"(  glossa zero-strain DECK.xml --output FILE [--method approximate|inverse] [--tolerance T]
         [--max-iterations N] [--set path=value ...] [--quiet]
      the zero-strain configuration (paper §8.1) of a deck loaded by gravity alone: approximate
      (the imaged mesh under the reversed gravity times 1.2) or inverse (reference coordinates
      updated until gravity maps them onto the imaged mesh, to T times the mean element edge);
      writes the coordinates to FILE (for Mesh/reference coordinates file) and a report to FILE
      with extension .json. The options stand for --set "Zero strain/method=..." etc.
)"},
    {"curves", R"(  glossa curves [--output DIR]
      tabulate the muscle curves f_cL, f_cV (both parameter sets), f_p and f_s to
      DIR/force_length.csv, force_velocity.csv, passive_series.csv (default DIR: ./curves)
)"},
};

const char *kFooter = R"(
--set overrides any deck parameter, e.g. --set Mesh/Box/cells=16,16,16 (for sweeps).
Exit status: 0 success; 1 the run stopped without converging (a step failed below the minimum
step size, or a check failed); 2 a bad deck, mesh file, command line or checkpoint; 3 the
run was interrupted (SIGTERM or SIGINT; summary.json says where); 4 an output file could not be
written (a full disk); 5 an internal error. Errors go to stderr, with --quiet too.
)";

// The help for `command` alone, or every command's when it names none of them.
std::string usage(const char *command) {
  std::string text = std::string(kHeader) + "\nusage:\n";
  bool found = false;
  for (const auto &c : kCommands)
    if (command && !std::strcmp(command, c.command)) {
      text += c.text;
      found = true;
    }
  if (!found) {
    for (const auto &c : kCommands) text += c.text;
    text += "  glossa --help | --version\n  glossa COMMAND --help\n";
  } else {
    text += "\nglossa --help lists every command.\n";
  }
  return text + kFooter;
}

struct Arguments {
  std::string command, deck, output, restart;
  std::vector<std::string> overrides;
  bool quiet = false, verbose = false, markdown = false, timers = false, json = false, print = false;
  std::string format = "auto";
  std::vector<std::string> zeroStrain; // --method, --tolerance, --max-iterations as deck overrides
  int refine = 0;
  int controlGroups = 1;
};

Arguments parse(int argc, char **argv) {
  Arguments a;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) throw glossa::io::DeckError("no command given; see glossa --help");
  a.command = args[0];
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string &s = args[i];
    auto value = [&](const char *flag) {
      if (i + 1 >= args.size()) throw glossa::io::DeckError(std::string(flag) + " needs a value");
      return args[++i];
    };
    if (s == "--output") a.output = value("--output");
    else if (s == "--restart") a.restart = value("--restart");
    else if (s == "--set") a.overrides.push_back(value("--set"));
    else if (s == "--quiet") a.quiet = true;
    else if (s == "--verbose") a.verbose = true;
    else if (s == "--timers") a.timers = true;
    else if (s == "--markdown") a.markdown = true;
    else if (s == "--json") a.json = true;
    else if (s == "--print") a.print = true;
    else if (s == "--format") a.format = value("--format");
    else if (s == "--method") a.zeroStrain.push_back("Zero strain/method=" + value("--method"));
    else if (s == "--tolerance") a.zeroStrain.push_back("Zero strain/tolerance=" + value("--tolerance"));
    else if (s == "--max-iterations") a.zeroStrain.push_back("Zero strain/maximum iterations=" + value("--max-iterations"));
    else if (s == "--refine") {
      const std::string v = value("--refine");
      try {
        std::size_t used = 0;
        a.refine = std::stoi(v, &used);
        if (used != v.size() || a.refine < 0 || a.refine > 4) throw std::invalid_argument(v);
      } catch (const std::exception &) {
        throw glossa::io::DeckError("--refine needs an integer in [0, 4], got '" + v + "'");
      }
    }
    else if (s == "--control-groups") {
      const std::string v = value("--control-groups");
      try {
        std::size_t used = 0;
        a.controlGroups = std::stoi(v, &used);
        if (used != v.size() || a.controlGroups < 1) throw std::invalid_argument(v);
      } catch (const std::exception &) {
        throw glossa::io::DeckError("--control-groups needs a positive integer, got '" + v + "'");
      }
    }
    else if (!s.empty() && s[0] == '-') throw glossa::io::DeckError("unknown option " + s + "; see glossa --help");
    else if (a.deck.empty()) a.deck = s;
    else throw glossa::io::DeckError("unexpected argument " + s + "; see glossa --help");
  }
  return a;
}

glossa::io::Deck loadDeck(const Arguments &a, const Teuchos::ParameterList &schema) {
  if (a.deck.empty()) throw glossa::io::DeckError("glossa " + a.command + " needs a deck file");
  auto deck = glossa::io::Deck::fromFile(a.deck);
  for (const auto &o : a.overrides) deck.applyOverride(o, schema);
  for (const auto &o : a.zeroStrain) deck.applyOverride(o, schema);
  deck.validate(schema);
  return deck;
}

// Exit statuses (kUsage and README list them).
constexpr int kNotConverged = 1, kBadInput = 2, kInterrupted = 3, kOutputFailed = 4, kInternalError = 5;

// Where main is: before `Collective`, every rank reads and checks the same deck and fails the same
// way, so each may return; in `Running`, one rank may fail alone while the others wait in a
// collective operation (MPI_Finalize would wait for them forever), so the error ends the job.
enum class Stage { Collective, Running };

int fail(const Teuchos::Comm<int> &comm, const std::string &message, int status, Stage stage) {
  const int rank = comm.getRank();
  if (stage == Stage::Collective || comm.getSize() == 1) {
    if (rank == 0) std::fprintf(stderr, "glossa: error: %s\n", message.c_str());
    return status;
  }
  // Rank 0's message comes first: if rank 0 failed too (the same error everywhere), it aborts
  // the job while the others wait, and the message is printed once.
  if (rank != 0) std::this_thread::sleep_for(std::chrono::seconds(2));
  if (rank == 0) std::fprintf(stderr, "glossa: error: %s\n", message.c_str());
  else std::fprintf(stderr, "glossa: error on rank %d: %s\n", rank, message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, status);
  return status;
}

} // namespace

int main(int argc, char **argv) {
  // Kokkos answers --help itself, wherever it stands (glossa mesh --help): ours comes first.
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h") || (i == 1 && !std::strcmp(argv[i], "help"))) {
      std::fputs(usage(argv[1]).c_str(), stdout);
      return 0;
    }
  glossa::app::separateIsolatedSingletonSession();
  Tpetra::ScopeGuard mpi(&argc, &argv);
  // A write past the file size limit (ulimit -f, a batch system's) fails with EFBIG, which ends
  // the run as a full disk does (exit status 4, the files so far whole, summary.json saying so),
  // instead of SIGXFSZ killing the process mid-write. mpiexec starts the ranks with the default
  // action, so each rank says it here.
  std::signal(SIGXFSZ, SIG_IGN);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  Stage stage = Stage::Collective;
  try {
    if (argc >= 2 && !std::strcmp(argv[1], "--version")) {
      if (root) std::puts("glossa " GLOSSA_VERSION);
      return 0;
    }
    const Arguments a = parse(argc, argv);
    if (!a.restart.empty() && a.command != "run")
      throw glossa::io::DeckError("--restart belongs to glossa run; see glossa --help");
    if (a.print && a.command != "validate")
      throw glossa::io::DeckError("--print belongs to glossa validate; see glossa --help");
    const Teuchos::ParameterList schema = glossa::app::deckSchema();
    if (a.command == "schema") {
      if (root) {
        if (a.markdown) glossa::io::writeDeckReference(schema, std::cout);
        else std::cout << glossa::io::Deck::fromList(schema, "schema").toXml();
      }
      return 0;
    }
    if (a.command == "curves") {
      if (!a.deck.empty() || !a.overrides.empty())
        throw glossa::io::DeckError("glossa curves takes no deck and no --set; see glossa --help");
      if (root)
        for (const auto &file : glossa::app::writeCurveTables(a.output.empty() ? "curves" : a.output))
          std::cout << "wrote " << file.string() << '\n';
      return 0;
    }
    if (a.command == "mesh") {
      if (a.deck.empty()) throw glossa::io::DeckError("glossa mesh needs a mesh file; see glossa --help");
      const auto report = glossa::app::describeMesh(a.deck, {a.format, a.refine, a.output});
      if (root) std::cout << (a.json ? report.dump(2) + "\n" : glossa::app::meshReportText(report));
      return 0;
    }
    if (a.command == "point") {
      const auto deck = loadDeck(a, schema);
      if (root) {
        const std::string file = a.output.empty() ? "point.csv" : a.output;
        const int rows = glossa::app::runPointDriver(deck, glossa::solvers::parseRunConfiguration(deck).time, file);
        std::cout << "wrote " << rows << " rows to " << file << '\n';
      }
      return 0;
    }
    if (a.command == "validate") {
      const auto deck = loadDeck(a, schema);
      // Building the scene checks what needs the mesh too (set names, named points), and the
      // checks across sections are run's own (a deck validate passes, run does not refuse).
      const auto config = glossa::solvers::parseRunConfiguration(deck);
      const auto scene = glossa::input::buildScene(deck, config.time.rampEndTime);
      glossa::input::buildAirway(deck, scene);  // its checks; the run builds it again
      glossa::solvers::checkRunConfiguration(deck, config, scene, glossa::solvers::buildControl(deck, scene),
                                             {comm->getSize(), a.controlGroups, !a.restart.empty()});
      if (root)
        for (const std::string &note : scene.meshNotes) std::fprintf(stderr, "glossa: note: %s\n", note.c_str());
      // The verdict on stderr, where the notes are: stdout keeps only the deck (--print), for a file.
      if (root) std::fprintf(stderr, "glossa: %s is valid\n", a.deck.c_str());
      if (root && a.print) std::cout << deck.toXml();
      return 0;
    }
    if (!a.zeroStrain.empty() && a.command != "zero-strain")
      throw glossa::io::DeckError("--method, --tolerance and --max-iterations belong to glossa zero-strain; see glossa --help");
    if (a.command == "zero-strain") {
      if (a.output.empty()) throw glossa::io::DeckError("glossa zero-strain needs --output FILE (the coordinates file)");
      const auto deck = loadDeck(a, schema);
      stage = Stage::Running;
      const auto result =
          glossa::app::computeZeroStrain(deck, glossa::solvers::parseRunConfiguration(deck), comm, a.output, a.quiet);
      if (!result.converged && root)
        std::fprintf(stderr, "glossa: zero-strain: max distance %.3e m after %d iterations is above the tolerance %.3e m\n",
                     result.maxDistance, result.iterations, result.tolerance);
      return result.converged ? 0 : kNotConverged;
    }
    if (a.command == "run") {
      const auto deck = loadDeck(a, schema);
      stage = Stage::Running;
      glossa::solvers::RunOptions options{a.output, a.quiet, a.verbose, a.controlGroups};
      options.restartDirectory = a.restart;
      const auto summary =
          glossa::solvers::runSimulation(deck, glossa::solvers::parseRunConfiguration(deck), comm, options);
      if (a.timers) Teuchos::TimeMonitor::summarize(comm.ptr(), std::cout, false, true, false);
      if (summary.contains("interrupted")) return kInterrupted;
      return summary.value("converged", false) ? 0 : kNotConverged;
    }
    throw glossa::io::DeckError("unknown command '" + a.command + "'; see glossa --help");
  } catch (const glossa::io::DeckError &e) {
    return fail(*comm, e.what(), kBadInput, stage);
  } catch (const glossa::mesh::MeshError &e) {
    return fail(*comm, e.what(), kBadInput, stage);
  } catch (const std::filesystem::filesystem_error &e) {
    return fail(*comm, std::string("cannot write the output: ") + e.what(), kOutputFailed, stage);
  } catch (const glossa::io::OutputError &e) {
    return fail(*comm, e.what(), kOutputFailed, stage);
  } catch (const std::exception &e) {
    return fail(*comm, e.what(), kInternalError, stage);
  }
}
