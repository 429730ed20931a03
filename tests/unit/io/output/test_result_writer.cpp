// ResultWriter: what it writes (the mesh file and one file per step) reads back exactly with the
// plain HDF5 C API, the XDMF index names exactly the datasets that exist, bad input is refused
// before anything is written, a run that stops (writer destroyed, or process killed) after a
// step leaves that step readable, and a step that does not fit on the disk (a file size limit)
// fails naming its file, leaves the earlier files readable and the process ending cleanly.

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "FileSizeLimit.hpp"
#include "Hdf5Reading.hpp"
#include "ScratchDirectory.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/ResultWriter.hpp"

namespace glossa::io {
namespace {

using testing::Hdf5File;
using testing::ScratchDirectory;

// Two unit hexahedra side by side along x, sharing the face x = 1; VTK node order per hex.
struct TwoHexMesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<std::int64_t, 8>> hexes;
  TwoHexMesh() {
    auto id = [](int i, int j, int k) { return static_cast<std::int64_t>(i + 3 * (j + 2 * k)); };
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) nodes.emplace_back(0.1 * i + 1.0 / 3.0, 1.7 * j, -0.3 * k);
    for (int i = 0; i < 2; ++i)
      hexes.push_back({id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1),
                       id(i + 1, 1, 1), id(i, 1, 1)});
  }
};

// Values that are not short decimals, so any rounding on the way would show.
Field makeField(const std::string &name, int components, std::size_t tuples, double seed) {
  Field f{name, components, {}};
  for (std::size_t i = 0; i < tuples * components; ++i) f.values.push_back((seed + i) / 7.0 + 1e-3 * i * i);
  return f;
}

struct StepData {
  double time;
  std::vector<Field> nodeFields, cellFields;
};

StepData makeStep(double time, double seed, const TwoHexMesh &mesh) {
  const auto n = mesh.nodes.size(), e = mesh.hexes.size();
  return {time,
          {makeField("displacement", 3, n, seed), makeField("temperature", 1, n, seed + 1)},
          {makeField("pressure", 1, e, seed + 2), makeField("cauchy_stress", 6, e, seed + 3),
           makeField("F", 9, e, seed + 4)}};
}

void write(ResultWriter &writer, const StepData &s) { writer.writeStep(s.time, s.nodeFields, s.cellFields); }

// What the file must hold for a field: its values, a symmetric tensor (xx, yy, zz, xy, yz, xz) as
// the full row-major 3x3 tensor.
std::vector<double> expectedValues(const Field &f) {
  if (f.components != 6) return f.values;
  std::vector<double> full;
  for (std::size_t t = 0; t < f.values.size(); t += 6) {
    const double *v = &f.values[t];
    full.insert(full.end(), {v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2]});
  }
  return full;
}

void expectStepReadsBack(const Hdf5File &file, const std::string &group, const StepData &s) {
  EXPECT_EQ(file.timeOf(group), s.time);
  for (const auto *fields : {&s.nodeFields, &s.cellFields})
    for (const Field &f : *fields) {
      const auto d = file.doubles(group + "/" + f.name);
      const std::size_t tuples = f.values.size() / f.components;
      const hsize_t written = f.components == 6 ? 9 : hsize_t(f.components);
      const std::vector<hsize_t> dims = f.components == 1 ? std::vector<hsize_t>{tuples}
                                                          : std::vector<hsize_t>{tuples, written};
      EXPECT_EQ(d.dims, dims) << f.name;
      EXPECT_EQ(d.values, expectedValues(f)) << f.name; // exact: bit-for-bit doubles
    }
}

void expectMeshReadsBack(const Hdf5File &file, const TwoHexMesh &mesh) {
  const auto xyz = file.doubles("/mesh/coordinates");
  ASSERT_EQ(xyz.dims, (std::vector<hsize_t>{mesh.nodes.size(), 3}));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(xyz.values[3 * i + c], mesh.nodes[i][c]);
  const auto topology = file.int64s("/mesh/topology");
  ASSERT_EQ(topology.dims, (std::vector<hsize_t>{mesh.hexes.size(), 8}));
  for (std::size_t e = 0; e < mesh.hexes.size(); ++e)
    for (int a = 0; a < 8; ++a) EXPECT_EQ(topology.values[8 * e + a], mesh.hexes[e][a]);
}

std::string readText(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The matches point into `text`, which must outlive them.
std::vector<std::smatch> matches(const std::string &text, const std::string &pattern) {
  const std::regex re(pattern);
  return {std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()};
}

// Step k's file of the run <base> in `dir`.
std::filesystem::path stepFile(const std::filesystem::path &dir, const std::string &base, int k) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%06d.h5", k);
  return dir / (base + "_steps") / name;
}

// Every HDF DataItem of the XDMF file must point into `<base>.h5` (the mesh) or a step file of
// `<base>_steps/`, at a dataset that exists with the declared dimensions; every dataset of those
// files must be referenced, and no other file (a leftover .tmp) may lie in the steps folder.
void expectXdmfMatchesHdf5(const std::filesystem::path &dir, const std::string &base) {
  const std::string text = readText(dir / (base + ".xdmf"));
  ASSERT_NE(text.find("</Xdmf>"), std::string::npos) << "XDMF file is incomplete";
  std::map<std::string, std::set<std::string>> referenced; // file -> datasets
  const std::string dataItem = R"re(<DataItem Dimensions="([^"]*)"[^>]*Format="HDF">([^<:]*):([^<]*)</DataItem>)re";
  for (const auto &m : matches(text, dataItem)) {
    const std::string name = m[2].str(), path = m[3].str();
    EXPECT_TRUE(name == base + ".h5" || name.rfind(base + "_steps/step_", 0) == 0) << name;
    referenced[name].insert(path);
    const Hdf5File file(dir / name);
    ASSERT_TRUE(file.hasLink(path)) << name << ":" << path;
    std::vector<hsize_t> dims;
    std::istringstream declared(m[1].str());
    for (hsize_t d; declared >> d;) dims.push_back(d);
    EXPECT_EQ(dims, file.doubles(path).dims) << path; // reading as double converts int64 exactly here
  }
  std::set<std::string> files{base + ".h5"};
  for (const auto &entry : std::filesystem::directory_iterator(dir / (base + "_steps")))
    files.insert(base + "_steps/" + entry.path().filename().string());
  for (const auto &name : files) EXPECT_EQ(referenced[name], Hdf5File(dir / name).datasetPaths()) << name;
}

std::vector<double> xdmfTimes(const std::filesystem::path &xdmf) {
  std::vector<double> times;
  const std::string text = readText(xdmf); // the matches point into it
  for (const auto &m : matches(text, R"re(<Time Value="([^"]*)"/>)re"))
    times.push_back(std::strtod(m[1].str().c_str(), nullptr));
  return times;
}

TEST(ResultWriter, TwoStepsReadBackExactly) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.1, 3.0, mesh), s1 = makeStep(1.0 / 3.0, 11.0, mesh);
  {
    ResultWriter writer(dir / "out", "results", mesh.nodes, mesh.hexes); // creates the missing directory
    write(writer, s0);
    write(writer, s1);
    EXPECT_EQ(writer.stepsWritten(), 2u);
  }
  expectMeshReadsBack(Hdf5File(dir / "out/results.h5"), mesh);
  expectStepReadsBack(Hdf5File(stepFile(dir / "out", "results", 0)), "/step_000000", s0);
  expectStepReadsBack(Hdf5File(stepFile(dir / "out", "results", 1)), "/step_000001", s1);
}

TEST(ResultWriter, XdmfNamesExactlyTheDatasetsAndBothTimes) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.1, 3.0, mesh), s1 = makeStep(1.0 / 3.0, 11.0, mesh);
  ResultWriter writer(dir.path(), "results", mesh.nodes, mesh.hexes);
  expectXdmfMatchesHdf5(dir.path(), "results"); // while the writer lives
  EXPECT_TRUE(xdmfTimes(writer.xdmfPath()).empty());
  write(writer, s0);
  write(writer, s1);
  expectXdmfMatchesHdf5(dir.path(), "results");
  EXPECT_EQ(xdmfTimes(writer.xdmfPath()), (std::vector<double>{s0.time, s1.time}));

  const std::string text = readText(writer.xdmfPath());
  EXPECT_NE(text.find(R"re(CollectionType="Temporal")re"), std::string::npos);
  EXPECT_EQ(matches(text, R"re(TopologyType="Hexahedron" NumberOfElements="2")re").size(), 2u);
  EXPECT_EQ(matches(text, R"re(GeometryType="XYZ")re").size(), 2u);
  const std::map<std::string, std::pair<std::string, std::string>> expected = {
      {"displacement", {"Vector", "Node"}}, {"temperature", {"Scalar", "Node"}}, {"pressure", {"Scalar", "Cell"}},
      {"cauchy_stress", {"Tensor", "Cell"}}, {"F", {"Tensor", "Cell"}}}; // the symmetric tensor written whole
  const auto attributes = matches(text, R"re(<Attribute Name="([^"]*)" AttributeType="([^"]*)" Center="([^"]*)">)re");
  EXPECT_EQ(attributes.size(), 2 * expected.size());
  for (const auto &m : attributes) EXPECT_EQ(expected.at(m[1].str()), std::make_pair(m[2].str(), m[3].str()));
  EXPECT_FALSE(std::filesystem::exists(dir / "results.xdmf.tmp"));
}

TEST(ResultWriter, RefusesBadFieldsBeforeWritingAnything) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  ResultWriter writer(dir.path(), "results", mesh.nodes, mesh.hexes);
  const Field good = makeField("pressure", 1, 2, 0.0);
  auto expectRefused = [&](const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields,
                           const std::string &mentioned, double time = 1.0) {
    try {
      writer.writeStep(time, nodeFields, cellFields);
      ADD_FAILURE() << "no exception for " << mentioned;
    } catch (const std::invalid_argument &e) {
      EXPECT_NE(std::string(e.what()).find(mentioned), std::string::npos) << e.what();
    }
  };
  Field shortVector = makeField("velocity", 3, mesh.nodes.size(), 0.0);
  shortVector.values.pop_back();
  expectRefused({shortVector}, {good}, "'velocity'");
  expectRefused({}, {good, makeField("stress", 6, 3, 0.0)}, "'stress'");        // node count, not cell count
  expectRefused({makeField("odd", 4, mesh.nodes.size(), 0.0)}, {}, "'odd'");    // 4 components
  expectRefused({makeField("pressure", 1, mesh.nodes.size(), 0.0)}, {good}, "'pressure'"); // same name twice
  expectRefused({}, {makeField("a/b", 1, 2, 0.0)}, "'a/b'");
  expectRefused({}, {good}, "not finite", std::nan(""));
  EXPECT_EQ(writer.stepsWritten(), 0u);
  EXPECT_TRUE(std::filesystem::is_empty(writer.stepsDirectory()));

  writer.writeStep(1.0, {}, {good});
  expectRefused({}, {good}, "not after", 1.0); // times must increase
  EXPECT_EQ(writer.stepsWritten(), 1u);
}

TEST(ResultWriter, RefusesTopologyNamingMissingNodes) {
  ScratchDirectory dir;
  TwoHexMesh mesh;
  mesh.hexes[1][6] = 12;
  EXPECT_THROW(ResultWriter(dir.path(), "results", mesh.nodes, mesh.hexes), std::invalid_argument);
  EXPECT_THROW(ResultWriter(dir.path(), "a/b", TwoHexMesh().nodes, TwoHexMesh().hexes), std::invalid_argument);
}

TEST(ResultWriter, WriterDestroyedAfterFirstStepLeavesItReadable) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.0, 5.0, mesh);
  {
    ResultWriter writer(dir.path(), "run", mesh.nodes, mesh.hexes);
    write(writer, s0);
  } // nothing else is called: the run "ends" here
  expectMeshReadsBack(Hdf5File(dir / "run.h5"), mesh);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "run", 0)), "/step_000000", s0);
  expectXdmfMatchesHdf5(dir.path(), "run");
  EXPECT_EQ(xdmfTimes(dir / "run.xdmf"), std::vector<double>{0.0});
}

// A running job: between steps a reader in another process that takes HDF5's file locks (as
// ParaView 5.11 does) opens the mesh file and the first step's, and the writer writes its next
// step while the reader still holds them. Before, the writer kept the file open with an
// exclusive lock and the reader's open failed.
TEST(ResultWriter, ARunningJobsFileOpensInALockingReaderAndTheRunGoesOn) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.0, 5.0, mesh), s1 = makeStep(0.5, 6.0, mesh);
  ResultWriter writer(dir.path(), "run", mesh.nodes, mesh.hexes);
  write(writer, s0);
  int opened[2], written[2];
  ASSERT_EQ(::pipe(opened), 0);
  ASSERT_EQ(::pipe(written), 0);
  const pid_t reader = ::fork();
  ASSERT_GE(reader, 0);
  if (reader == 0) { // the reader: open with locks, say so, hold the file until the step is written
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_file_locking(fapl, true, false);
    const hid_t file = H5Fopen((dir / "run.h5").c_str(), H5F_ACC_RDONLY, fapl);
    const hid_t step = H5Fopen(stepFile(dir.path(), "run", 0).c_str(), H5F_ACC_RDONLY, fapl);
    const char ok = file >= 0 && step >= 0 ? 'y' : 'n';
    [[maybe_unused]] auto n = ::write(opened[1], &ok, 1);
    char done = 0;
    n = ::read(written[0], &done, 1);
    ::_exit(file >= 0 && step >= 0 && H5Fclose(file) >= 0 && H5Fclose(step) >= 0 ? 0 : 1);
  }
  char ok = 0;
  ASSERT_EQ(::read(opened[0], &ok, 1), 1);
  EXPECT_EQ(ok, 'y') << "a locking reader cannot open a running job's file";
  EXPECT_NO_THROW(write(writer, s1)); // while the reader holds the file
  const char done = 'd';
  ASSERT_EQ(::write(written[1], &done, 1), 1);
  int status = 0;
  ASSERT_EQ(::waitpid(reader, &status, 0), reader);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "run", 1)), "/step_000001", s1);
}

// A real kill: the child process writes one step and dies by SIGKILL with the HDF5 file still
// open (no destructor, no H5Fclose). Both files must still read back.
TEST(ResultWriter, KilledProcessLeavesWrittenStepReadable) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.25, 9.0, mesh);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      ResultWriter writer(dir.path(), "killed", mesh.nodes, mesh.hexes);
      write(writer, s0);
      ::raise(SIGKILL);
    } catch (...) {
    }
    ::_exit(3);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the child failed before being killed";
  expectMeshReadsBack(Hdf5File(dir / "killed.h5"), mesh);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "killed", 0)), "/step_000000", s0);
  expectXdmfMatchesHdf5(dir.path(), "killed");
  EXPECT_EQ(xdmfTimes(dir / "killed.xdmf"), std::vector<double>{0.25});
}

// A restart (glossa run --restart) resumes the files from a checkpoint made after two steps: the
// third step, written before the run was killed, goes (with a step file the kill cut short), and
// the steps written after the restart follow the first two as if the run had never stopped.
TEST(ResultWriter, ResumedAtACheckpointDropsTheLaterStepsAndCarriesOn) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.1, 3.0, mesh), s1 = makeStep(0.2, 5.0, mesh), s2 = makeStep(0.3, 7.0, mesh),
                 again = makeStep(0.3, 13.0, mesh), s3 = makeStep(0.4, 17.0, mesh);
  std::vector<XdmfStep> atCheckpoint;
  {
    ResultWriter writer(dir.path(), "results", mesh.nodes, mesh.hexes);
    write(writer, s0);
    write(writer, s1);
    atCheckpoint = writer.steps();
    write(writer, s2);
  }
  // A kill while step 4 was being written left its .tmp, which the restart removes.
  std::ofstream(stepFile(dir.path(), "results", 4).string() + ".tmp") << "cut short";
  {
    ResultWriter writer(dir.path(), "results", mesh.nodes.size(), mesh.hexes.size(), atCheckpoint);
    EXPECT_EQ(xdmfTimes(dir / "results.xdmf"), (std::vector<double>{0.1, 0.2}));
    EXPECT_FALSE(std::filesystem::exists(stepFile(dir.path(), "results", 2)));
    EXPECT_FALSE(std::filesystem::exists(stepFile(dir.path(), "results", 4).string() + ".tmp"));
    write(writer, again);
    write(writer, s3);
  }
  EXPECT_EQ(xdmfTimes(dir / "results.xdmf"), (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
  expectMeshReadsBack(Hdf5File(dir / "results.h5"), mesh);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "results", 1)), "/step_000001", s1);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "results", 2)), "/step_000002", again);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "results", 3)), "/step_000003", s3);
  expectXdmfMatchesHdf5(dir.path(), "results");
}

TEST(ResultWriter, ResumingAMissingFileIsAnOutputError) {
  ScratchDirectory dir;
  EXPECT_THROW(ResultWriter(dir.path(), "results", 12, 2, {}), std::runtime_error);
}

TEST(ResultWriter, NewRunReplacesEarlierFiles) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  {
    ResultWriter first(dir.path(), "results", mesh.nodes, mesh.hexes);
    write(first, makeStep(1.0, 0.0, mesh));
  }
  ResultWriter second(dir.path(), "results", mesh.nodes, mesh.hexes);
  EXPECT_FALSE(std::filesystem::exists(stepFile(dir.path(), "results", 0)));
  expectXdmfMatchesHdf5(dir.path(), "results");
}

TEST(ResultWriter, H5dumpReadsTheFileWhenInstalled) {
  if (!std::filesystem::exists("/usr/bin/h5dump")) GTEST_SKIP() << "/usr/bin/h5dump not installed";
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  {
    ResultWriter writer(dir.path(), "results", mesh.nodes, mesh.hexes);
    write(writer, makeStep(0.5, 1.0, mesh));
  }
  for (const auto &file : {dir / "results.h5", stepFile(dir.path(), "results", 0)}) {
    const std::string command = "/usr/bin/h5dump -H " + file.string() + " > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << file;
  }
}

// A full disk, as RLIMIT_FSIZE makes one (SIGXFSZ ignored: a write past the limit fails with
// EFBIG, as one on a full disk fails with ENOSPC): a child process writes the mesh and a first
// step, then a step with many more fields than fit. Before, HDF5 wrote the file itself; its
// failed flush left the file open inside HDF5, and closing it again at exit crashed the process.
TEST(ResultWriter, AStepPastAFullDiskFailsNamingItsFileAndLeavesTheEarlierOnesReadable) {
  ScratchDirectory dir;
  const TwoHexMesh mesh;
  const StepData s0 = makeStep(0.5, 2.0, mesh);
  StepData big = makeStep(1.0, 4.0, mesh);
  for (int k = 0; k < 400; ++k) big.nodeFields.push_back(makeField("extra_" + std::to_string(k), 9, mesh.nodes.size(), k));
  // The first step's file is a few KB, the big one's over 300 KB.
  const std::string ended = testing::underFileSizeLimit(64 * 1024, [&] {
    try {
      ResultWriter writer(dir.path(), "run", mesh.nodes, mesh.hexes);
      write(writer, s0);
      try {
        write(writer, big);
      } catch (const OutputError &e) {
        const std::string what = e.what(); // the step's own file, and why
        const bool named = what.find("run_steps/step_000001.h5") != std::string::npos;
        return named && what.find("File too large") != std::string::npos ? 0 : 13;
      }
      return 12;
    } catch (const OutputError &) {
      return 11;
    }
  });
  ASSERT_EQ(ended, "exit 0") << "100: no limit; 11: the first step failed; 12: nothing failed; 13: another message";
  expectMeshReadsBack(Hdf5File(dir / "run.h5"), mesh);
  expectStepReadsBack(Hdf5File(stepFile(dir.path(), "run", 0)), "/step_000000", s0);
  expectXdmfMatchesHdf5(dir.path(), "run"); // also: no step_000001.h5, no leftover .tmp
  EXPECT_EQ(xdmfTimes(dir / "run.xdmf"), std::vector<double>{0.5});
}

} // namespace
} // namespace glossa::io
