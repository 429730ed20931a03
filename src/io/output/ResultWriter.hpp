#pragma once
// Fields of a run as a time series ParaView opens: <base>.h5 holds the mesh (/mesh/coordinates
// N x 3 float64, /mesh/topology E x 8 int64 in VTK hexahedron order), written once;
// <base>_steps/step_000000.h5, step_000001.h5, ... each hold one written step (group
// /step_NNNNNN with a "time" attribute and one dataset per field); <base>.xdmf (XDMF 3, a
// temporal collection, XdmfTimeSeries.hpp) points into them.
//
// Rank 0 writes (the caller gathers global arrays first). No file a reader can see is ever being
// changed: each HDF5 file is built in memory and its image replaces the file on disk whole
// (AtomicFile.hpp: written under <name>.tmp, synced, renamed), and only then is the XDMF file
// replaced the same way, so it never names data that is not on disk yet. A write that fails (a
// full disk) throws OutputError naming the file and leaves every file written before it intact. ParaView thus opens a running job's files as they are, and a run
// killed at any moment leaves every step written so far readable. (With all steps in one file,
// a reader that opened it while the writer added a step could meet its metadata in flux:
// pvpython aborted with "not a dataspace" about once in six runs of the test that reads a
// running job.) The files are written without HDF5's file locks.
//
// A symmetric tensor field (6 components, xx, yy, zz, xy, yz, xz) is written as the full 3x3
// tensor (9 components, row-major, AttributeType "Tensor"): ParaView 5.11's two XDMF readers
// disagree on "Tensor6" (Xdmf3ReaderS passes the six values through in VTK's order xx, yy, zz,
// xy, yz, xz; the legacy XDMFReader reads them in the XDMF standard's xx, xy, xz, yy, yz, zz), so
// either order shows sigma_yy as sigma_xy in one of them; nine components read alike in both
// (tests/integration/paraview_readers.py).

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/output/Field.hpp"
#include "io/output/XdmfTimeSeries.hpp"

namespace glossa::io {

class ResultWriter {
public:
  // Creates `directory` if missing and replaces any earlier <baseName>.h5/.xdmf/_steps there. Throws
  // std::invalid_argument for a base name that is not a plain file name or a hexahedron that
  // names a node outside `nodes`, std::runtime_error if the files cannot be written.
  ResultWriter(const std::filesystem::path &directory, const std::string &baseName,
               const std::vector<Eigen::Vector3d> &nodes,
               const std::vector<std::array<std::int64_t, 8>> &hexes);
  // A restart's: keeps the existing <baseName>.h5 and step files, removes the step files after
  // the first `resumeSteps.size()` (written after the checkpoint) and carries on from
  // `resumeSteps` (what steps() said at the checkpoint). Throws std::runtime_error if the mesh
  // file cannot be opened or a step file of the checkpoint is missing.
  ResultWriter(const std::filesystem::path &directory, const std::string &baseName, std::size_t numNodes,
               std::size_t numCells, std::vector<XdmfStep> resumeSteps);
  ~ResultWriter();
  ResultWriter(const ResultWriter &) = delete;
  ResultWriter &operator=(const ResultWriter &) = delete;

  // Node fields have one tuple per node, cell fields one per hexahedron. Everything is checked
  // before anything is written; std::invalid_argument names the offending field when its size is
  // not n * components, its components are not 1, 3, 6 or 9, its name is empty, contains '/' or
  // repeats another field's; also when `time` is not finite or not after the previous step's.
  void writeStep(double time, const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields);
  std::size_t stepsWritten() const { return steps_.size(); }
  const std::vector<XdmfStep> &steps() const { return steps_; }

  std::filesystem::path hdf5Path() const { return directory_ / (baseName_ + ".h5"); } // the mesh
  std::filesystem::path xdmfPath() const { return directory_ / (baseName_ + ".xdmf"); }
  // Step k's file, relative to the directory ("<base>_steps/step_00000k.h5"), and their folder.
  std::string stepFile(std::size_t index) const;
  std::filesystem::path stepsDirectory() const;

private:
  void checkStep(double time, const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields) const;
  void writeXdmf() const;

  std::filesystem::path directory_;
  std::string baseName_;
  XdmfMesh mesh_;
  std::vector<XdmfStep> steps_;
};

} // namespace glossa::io
