#pragma once
// Writes what a run records of every converged step: the traced points (traces.csv), the
// reactions of the Dirichlet conditions (reactions.csv), the muscle groups' input, activation,
// FFMR and mean fibre and contractile stretch (activation.csv), the contacts (contact.csv), and, every `Output/every` steps, the fields for
// ParaView (results.h5 and results_steps/ + XDMF: displacement, element pressure, dilatation, J, Cauchy stress and,
// with muscles, fibre stress, directions, stretches and muscle sets; in a dynamic run velocity and
// acceleration) and a dynamic run's energies (energy.csv). Every rank gathers; the writer rank
// writes.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "assembly/MuscleResponse.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "contact/ContactMeasures.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/ResultWriter.hpp"
#include "io/output/TraceWriter.hpp"
#include "solvers/run/AirflowStep.hpp"
#include "solvers/run/AirwayRecorder.hpp"

namespace glossa::solvers {

class Inertia;

// A dynamic step's energies [J]: kinetic (1/2) v.M v and stored (assembly::ResultEvaluator::storedEnergy).
struct StepEnergy {
  double kinetic = 0.0, stored = 0.0;
  double total() const { return kinetic + stored; }
};

// How far every file had got when a checkpoint was made (the writer rank's): a restart cuts each
// back to it, so the files end as an uninterrupted run's would.
struct OutputMark {
  std::map<std::string, std::uintmax_t> csvBytes; // by file name
  std::vector<io::XdmfStep> fieldSteps;           // the field steps written (results_steps/)
};

class StepRecorder {
public:
  // `results`: what every step is recorded from (kept as a copy: it is a view of the assembler).
  // `writer`: this rank writes the files (rank 0 of the world; with control groups every group
  // records, collectively on its own communicator, but only one rank writes).
  // `airway`: the deck's Airway section (input::buildAirway), recorded every step; null: none.
  // `resultantSets`, `volumeSets`: face sets (existing) whose resultant force and enclosed volume
  // are written every step to resultants.csv and volumes.csv.
  StepRecorder(const assembly::ResultEvaluator &results, const std::filesystem::path &dir, bool fields, bool writer,
               std::vector<std::string> resultantSets = {}, std::vector<std::string> volumeSets = {},
               const OutputMark *resume = nullptr, bool dynamic = false,
               std::shared_ptr<const model::AirwayOutput> airway = nullptr);
  // A dynamic run's inertia (outliving this recorder), whose velocity and acceleration every
  // field step then carries.
  void showInertia(const Inertia *inertia) { inertia_ = inertia; }
  // One row of energy.csv (dynamic runs; writer rank only).
  void recordEnergy(double time, const StepEnergy &energy);

  // Where the files are now (empty on the ranks that do not write).
  OutputMark mark() const;

  // Displacement of every traced point (on every rank).
  std::vector<std::pair<std::string, Eigen::Vector3d>> pointDisplacements(const std::vector<double> &u) const;

  // Per muscle group: u, alpha, FFMR = T0s alpha (§6) and the length-weighted mean fibre and
  // contractile stretches, as written
  // to activation.csv (the converged step's values, before they are committed).
  std::vector<std::pair<std::string, std::vector<double>>> activationRows(const assembly::MuscleFields &muscle,
                                                                          const std::vector<double> &input) const;

  // The reaction of every Dirichlet condition: fx, fy, fz [N] and its power [W] (collective).
  std::vector<std::pair<std::string, std::vector<double>>> reactionRows(const assembly::Vector &u, double time,
                                                                        const std::vector<double> &lambda) const;

  // Records one converged step (collective); returns the reactions it wrote (for the summary).
  // `fieldsTime`: the fields' time in results.xdmf if not `time`, which ParaView needs increasing
  // (an arc-length path's time falls past a load maximum: its fields are stamped with the step).
  std::vector<std::pair<std::string, std::vector<double>>> record(double time, const assembly::Vector &u,
                                                                  const std::vector<double> &lambda, bool writeFields,
                                                                  const assembly::MuscleFields &muscle,
                                                                  const std::vector<double> &input,
                                                                  std::optional<double> fieldsTime = std::nullopt);

  // One row per contact in contact.csv: area, normal force, largest penetration, active points
  // and largest gap error of a converged step (the Uzawa loop's measures; writer rank only).
  void recordContacts(double time, const std::vector<contact::ContactMeasures> &contacts);
  // The airway's lumen at the state the last record() was given, with the contacts' areas (a
  // scene with an Airway section; writer rank only; doc/airway.md).
  void recordAirway(double time, const std::vector<contact::ContactMeasures> &contacts);
  // One row of airflow.csv (a scene with airflow; writer rank only; doc/airflow.md): the flow rate,
  // the end pressures, the smallest section, the coupling's iterations and last change, and every
  // section's pressure.
  void recordAirflow(double time, const AirflowStep &airflow);

private:
  // The node fields of a step: the displacement (all nodes) and, with contacts, their pressure
  // and gap (assembly::contactNodeFields). Collective.
  std::vector<io::Field> nodeFields(const std::vector<double> &uAll) const;

  const assembly::ResultEvaluator evaluator_;
  bool root_, fields_;
  std::unique_ptr<io::ResultWriter> results_;
  std::unique_ptr<io::TraceWriter> traces_;
  std::unique_ptr<io::KeyedCsvWriter> activation_, reactions_, resultants_, volumes_, contacts_, energy_, airflow_;
  std::shared_ptr<const model::AirwayOutput> airwayModel_;
  std::unique_ptr<AirwayRecorder> airway_;
  std::vector<Eigen::Vector3d> airwayPositions_; // the tongue surface's vertices at the last record()
  const Inertia *inertia_ = nullptr;
  std::vector<std::string> resultantSets_, volumeSets_;
  std::map<std::string, std::vector<double>> fibreDirections_; // rank 0, per family
  std::vector<std::pair<std::string, std::vector<double>>> groupMembership_; // per group, per element
};

} // namespace glossa::solvers
