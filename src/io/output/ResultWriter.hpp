#pragma once
// Fields of a run as a time series ParaView opens: <base>.h5 holds the mesh once and one group
// per written step; <base>.xdmf (XDMF 3, a temporal collection) points into it. Rank 0 writes
// (the caller gathers). After every step the HDF5 file is flushed and the XDMF file replaced
// atomically (temporary file + rename), so a run stopped at any moment leaves both readable.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "io/output/Field.hpp"

namespace glossa::io {

class ResultWriter {
public:
  ResultWriter(const std::filesystem::path &directory, const std::string &baseName,
               const std::vector<Eigen::Vector3d> &nodes,
               const std::vector<std::array<std::int64_t, 8>> &hexes);
  ~ResultWriter();
  ResultWriter(const ResultWriter &) = delete;
  ResultWriter &operator=(const ResultWriter &) = delete;

  // Node fields have one tuple per node, cell fields one per hexahedron.
  void writeStep(double time, const std::vector<Field> &nodeFields, const std::vector<Field> &cellFields);
  std::size_t stepsWritten() const { return steps_.size(); }

private:
  struct StepRecord {
    double time;
    std::string group;
    std::vector<std::pair<Field, bool>> fields; // (name/components only, isNode)
  };
  void writeXdmf() const;

  std::filesystem::path directory_;
  std::string baseName_;
  std::size_t numNodes_, numCells_;
  std::int64_t file_; // hid_t
  std::vector<StepRecord> steps_;
};

} // namespace glossa::io
