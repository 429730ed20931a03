#pragma once
// Fields of a run as a time series ParaView opens: <base>.h5 holds the mesh once
// (/mesh/coordinates N x 3 float64, /mesh/topology E x 8 int64 in VTK hexahedron order) and one
// group per written step (/step_000000, /step_000001, ... with a "time" attribute and one dataset
// per field); <base>.xdmf (XDMF 3, a temporal collection, XdmfTimeSeries.hpp) points into it.
//
// Rank 0 writes (the caller gathers global arrays first). A run killed between calls leaves both
// files readable with every step written so far: after a step the HDF5 file is flushed and
// closed, and only then is the XDMF file replaced atomically (AtomicFile.hpp), so it never names
// data that is not on disk yet.
//
// A symmetric tensor field (6 components, xx, yy, zz, xy, yz, xz) is written as the full 3x3
// tensor (9 components, row-major, AttributeType "Tensor"): ParaView 5.11's two XDMF readers
// disagree on "Tensor6" (Xdmf3ReaderS passes the six values through in VTK's order xx, yy, zz,
// xy, yz, xz; the legacy XDMFReader reads them in the XDMF standard's xx, xy, xz, yy, yz, zz), so
// either order shows sigma_yy as sigma_xy in one of them; nine components read alike in both
// (tests/integration/paraview_readers.py). The .h5 is open only while a step is written, and without HDF5's
// file locks, so ParaView opens a running job's files as they are. HDF5 itself has no journal: a kill *during* the flush of a step can still damage
// the .h5 file; that window is milliseconds per step.

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
  // Creates `directory` if missing and replaces any earlier <baseName>.h5/.xdmf there. Throws
  // std::invalid_argument for a base name that is not a plain file name or a hexahedron that
  // names a node outside `nodes`, std::runtime_error if the files cannot be written.
  ResultWriter(const std::filesystem::path &directory, const std::string &baseName,
               const std::vector<Eigen::Vector3d> &nodes,
               const std::vector<std::array<std::int64_t, 8>> &hexes);
  // A restart's: keeps the existing <baseName>.h5, drops its steps after the first
  // `resumeSteps.size()` (written after the checkpoint) and carries on from `resumeSteps` (what
  // steps() said at the checkpoint). Throws std::runtime_error if the file cannot be opened (a
  // kill during an HDF5 flush can damage it).
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

  std::filesystem::path hdf5Path() const { return directory_ / (baseName_ + ".h5"); }
  std::filesystem::path xdmfPath() const { return directory_ / (baseName_ + ".xdmf"); }

private:
  void checkStep(double time, const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields) const;
  void writeXdmf() const;

  std::filesystem::path directory_;
  std::string baseName_;
  XdmfMesh mesh_;
  std::vector<XdmfStep> steps_;
};

} // namespace glossa::io
