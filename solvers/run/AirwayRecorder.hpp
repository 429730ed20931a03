#pragma once
// Writes the airway's lumen of every recorded step (doc/airway.md): airway.csv, one row a step
// (each section's area, the smallest and where it is, the tongue-wall contact area, whether the
// airway is closed and how many sections are), airway_sections.csv (each section's place along
// the centreline, once), and the sections' outlines for ParaView, one legacy VTK polydata file a
// step in airway_sections/ listed with their times in airway_sections.vtk.series. Writer rank only.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "contact/ContactMeasures.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "model/AirwayOutput.hpp"

namespace glossa::solvers {

class AirwayRecorder {
public:
  // `resumeAt`: a restart's length of airway.csv at the checkpoint; the outlines already written
  // up to it are kept and listed again.
  AirwayRecorder(const model::AirwayOutput &airway, const std::filesystem::path &dir,
                 std::optional<std::uintmax_t> resumeAt);

  // The lumen with the tongue's vertices at `positions`, and the contact area of the deck's
  // airway contact from `contacts` (0 without one).
  void record(double time, const std::vector<Eigen::Vector3d> &positions,
              const std::vector<contact::ContactMeasures> &contacts);

  const io::KeyedCsvWriter &csv() const { return *csv_; }

private:
  void writeSectionsTable() const;
  void writeOutlines(const airway::LumenState &state) const;
  void writeSeries() const;

  const model::AirwayOutput &airway_;
  std::filesystem::path dir_;
  std::unique_ptr<io::KeyedCsvWriter> csv_;
  std::vector<double> times_;  // of the outline files written, in order
};

}  // namespace glossa::solvers
