#!/usr/bin/env python3
"""The style checks can fail: each runs on a small tree written here, once with planted
violations (it must fail and name exactly the planted lines or folders) and once without them
(it must pass).

    style_checks_selftest.py
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# Legitimate code the deck-read check must leave alone: parsing-layer reads, lists built for
# NOX/Belos and read back from them, nlohmann::json, a summary's root(), other where()/given.
CLEAN = {
    "src/io/deck/Deck.hpp": """
class Deck {
public:
  static Deck fromFile(const std::string &path);
  Teuchos::ParameterList &root() { return list_; }
};
""",
    "src/input/TimeSection.cpp": """
double endTimeOf(const io::Deck &deck) {
  const Teuchos::ParameterList &t = deck.root().sublist("Time");
  if (!deck.given({"Time", "end time"})) return 1.0;
  return t.get<double>("end time");
}
""",
    "solvers/parameters/OutputSection.cpp": """
std::string whereEvery(const io::Deck &deck) { return deck.where({"Output", "every"}); }
""",
    "solvers/nonlinear/Newton.cpp": """
// NOX's own lists: deck.root() in a comment does not count, nor "deck.root()" in a string.
void configure(Teuchos::RCP<Teuchos::ParameterList> params, const Teuchos::ParameterList &p) {
  params->sublist("Printing").set("Output Information", 0);
  auto &newton = params->sublist("Direction").sublist("Newton");
  newton.sublist("Linear Solver").set("Tolerance", 1e-8);
  const char *text = "deck.root().sublist(\\"Time\\")";
  if (p.isSublist("Output") && p.sublist("Output").isType<int>("Number of Linear Iterations"))
    iterations = p.sublist("Output").get<int>("Number of Linear Iterations");
}
""",
    "solvers/linear/Mumps.cpp": """
bool symmetric(const Teuchos::RCP<Teuchos::ParameterList> &params_) { return params_->get<bool>("symmetric", true); }
""",
    "src/io/output/Summary.cpp": """
void write(SummaryWriter *summary_, const nlohmann::json &r) {
  summary_->root() = r;
  const double v = r.at("scaled_jacobian").at("min").get<double>();
  auto history = std::make_unique<History>();
  History *raw = history.get();
}
""",
    "src/model/Fibres.cpp": """
void read(std::istream &in) {
  auto where = [&]() { return std::string("line 3: "); };
  std::vector<char> given(3, 0);
  if (given[1]) throw std::runtime_error(where() + "given twice");
}
""",
    "src/app/Command.cpp": """
int run(const io::Deck &deck, const solvers::TimeParameters &time) {
  const input::PointParameters point = input::parsePointParameters(deck, time.steps.endTime);
  std::cout << deck.file() << deck.toXml();
  return point.times.size();
}
""",
}

# Deck reads outside the parsing layer, each line that must be reported marked "// <-".
PLANTED = {
    "src/app/Planted.cpp": """
int endTime(const io::Deck &deck) {
  return parseTimeParameters(deck.root().sublist("Time")).steps.endTime; // <-
}
void point(const io::Deck &deck) {
  const Teuchos::ParameterList &p = deck.root().sublist("Point"); // <-
  const auto kind = p.get<std::string>("path"); // <-
  const auto &f = p.sublist("time function"); // <-
  if (f.get<std::string>("type") == "ramp") return; // <-
}
""",
    "solvers/run/Run.cpp": """
Run::Run(const io::Deck &deck) {
  const auto &D = deck.root(); // <-
  every_ = D.sublist("Output") // <-
               .get<int>("every");
  if (deck
          .given({"Linear solver", "preconditioner"})) // <-
    warn();
  const std::string why = deck_.where({"Time", "path following"}); // <-
}
""",
    "solvers/run/RunParts.hpp": """
struct Parts {
  const io::Deck &deck_;
  const io::Deck *input;
};
""",
    "control/Uses.cpp": """
void use(const Parts &parts) {
  if (parts.input->root().isParameter("Control")) return; // <-
  std::string s = anything.where({"Control", "type"}); // <-
}
""",
    "materials/Load.cpp": """
io::Deck loadDeck(const std::string &file);
void load(const std::string &file) {
  auto d = glossa::io::Deck::fromFile(file);
  d.validate(schema);
  const double nu = d.root().sublist("Material").get<double>("Poisson's ratio"); // <-
  const int n = loadDeck(file).root().sublist("Time").get<int>("arc length steps"); // <-
}
""",
}


def write_tree(root, files):
    for path, text in files.items():
        os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
        with open(os.path.join(root, path), "w", encoding="utf-8") as f:
            f.write(text)


def run(script, root, *args):
    result = subprocess.run([sys.executable, os.path.join(HERE, script), *args], cwd=root, capture_output=True,
                            text=True)
    return result.returncode, result.stdout + result.stderr


def reported(output):
    """What each reported line names first ('path:line' or a folder); the summary line, which
    starts with a count, names nothing."""
    return {line.split(": ", 1)[0] for line in output.splitlines() if line and not line[0].isdigit()}


def check(condition, what, output):
    if not condition:
        print(f"FAILED: {what}\n--- output ---\n{output}")
    return condition


def deck_reads_case():
    ok = True
    folders = ("src", "solvers", "control", "materials")
    with tempfile.TemporaryDirectory() as root:
        write_tree(root, CLEAN)
        status, output = run("deck_reads.py", root, *folders)
        ok &= check(status == 0 and not reported(output), "deck_reads.py passes legitimate code", output)
        write_tree(root, PLANTED)
        status, output = run("deck_reads.py", root, *folders)
        expected = {f"{os.path.normpath(path)}:{number}" for path, text in PLANTED.items()
                    for number, line in enumerate(text.split("\n"), start=1) if line.endswith("// <-")}
        ok &= check(status == 1, "deck_reads.py fails on planted deck reads", output)
        ok &= check(reported(output) == expected,
                    f"deck_reads.py reports exactly {sorted(expected)}, got {sorted(reported(output))}", output)
    return ok


def mirrors_case():
    ok = True
    tree = {
        "src/fem/Shape.cpp": "", "src/fem/Shape.hpp": "",
        "src/io/deck/Deck.cpp": "",
        "src/model/Scene.hpp": "",  # headers only: no tests needed
        "materials/Law.cpp": "", "materials/fit/fit.py": "",
        "solvers/linear/Factory.cpp": "",
        "tests/unit/fem/test_shape.cpp": "", "tests/unit/io/deck/test_deck.cpp": "",
        "tests/unit/materials/test_law.cpp": "", "tests/unit/solvers/linear/test_factory.cpp": "",
        "tests/unit/fem/CMakeLists.txt": "add_executable(unit_fem test_shape.cpp)\n",
        "tests/unit/io/deck/CMakeLists.txt": "add_executable(unit_deck test_deck.cpp)\n",
        "tests/unit/materials/CMakeLists.txt": "add_executable(unit_materials\n  test_law.cpp)\n",
        "tests/unit/solvers/CMakeLists.txt": "add_executable(unit_solvers linear/test_factory.cpp)\n",
    }
    folders = ("materials", "control", "src", "solvers")
    with tempfile.TemporaryDirectory() as root:
        write_tree(root, tree)
        status, output = run("unit_test_mirrors.py", root, *folders)
        ok &= check(status == 0 and not reported(output), "unit_test_mirrors.py passes mirrored folders", output)
        write_tree(root, {"src/app/main.cpp": "", "solvers/run/Run.cpp": "",
                          "tests/unit/solvers/run/test_run.cpp": "",  # there, but built by nothing
                          "control/Ga.cpp": "", "tests/unit/control/GaTestSupport.hpp": "",
                          "tests/unit/app/CMakeLists.txt": "# test_main.cpp: only named in a comment\n"})
        status, output = run("unit_test_mirrors.py", root, *folders)
        ok &= check(status == 1, "unit_test_mirrors.py fails on unmirrored folders", output)
        ok &= check(reported(output) == {"src/app", "solvers/run", "control"},
                    f"unit_test_mirrors.py names src/app, solvers/run and control, got {sorted(reported(output))}",
                    output)
    return ok


def main():
    results = [deck_reads_case(), mirrors_case()]
    print(f"{results.count(False)} of {len(results)} style self-tests failed")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
