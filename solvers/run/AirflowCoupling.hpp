#pragma once
// The airflow coupled to the solid at every step (doc/airflow.md, "Coupling"): a partitioned
// fixed-point iteration on the pressures of the lumen's sections. Each iteration maps the
// sections' pressures onto the airway faces (the scene's airflow load), solves the solid, measures
// the lumen of the deformed tongue and solves the flow through it; the step is coupled when no
// section's pressure changes by more than the deck's tolerance, the solid then in equilibrium under
// pressures the flow reproduces to that tolerance. The update between iterations is the deck's
// coupling method (airflow/CouplingIteration). The iterations run either around whole step solves
// (each a converged Uzawa loop) or inside the Uzawa loop, one per Newton solve beside the
// multipliers' update (StepCoupling::afterSolve as the loop's outer condition). The first iterate
// is the flow through the lumen of the step's starting state, so a step depends on nothing but that
// state (a restart needs no coupling history). Every rank measures the same lumen from the
// gathered displacement, so all ranks take the same decisions.

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "airflow/AirwayFlow.hpp"
#include "input/AirflowParameters.hpp"
#include "model/AirwayOutput.hpp"
#include "model/Scene.hpp"
#include "solvers/run/AirflowStep.hpp"

namespace glossa::solvers {

class AirflowCoupling {
public:
  // `scene.airflowLoad` the load the coupling sets; `airway` the lumen (the Airway section).
  AirflowCoupling(const input::AirflowParameters &parameters, std::shared_ptr<const model::AirwayOutput> airway,
                  const model::Scene &scene);

  // One step's coupling iterations.
  class StepCoupling {
  public:
    enum class Verdict { coupled, again, failed };
    // Sets the face pressures to the flow through the lumen at `uStart` (every node's
    // displacement), the step's start; a lumen the flow cannot pass fails at once (result()).
    StepCoupling(const AirflowCoupling &coupling, double time, const std::vector<double> &uStart, bool progress);
    bool started() const { return result_.why.empty(); }
    // The displacement of every node per pascal on each section's faces (one vector per section,
    // as `uAll`), through the solid's tangent at the state just solved: what Newton's coupling
    // method measures its Jacobian from. Collective.
    using SectionResponses = std::function<std::vector<std::vector<double>>()>;
    // After a solid solve that reached `uAll`: the flow through its lumen; coupled when no
    // section's pressure changes by more than the tolerance, else the next face pressures are
    // set (again), or the iterations are spent or the flow fails (failed). Newton's method asks
    // `responses` once a step, at its first update; without them it relaxes.
    Verdict afterSolve(const std::vector<double> &uAll, const SectionResponses &responses = {});
    const AirflowStep &result() const { return result_; }

  private:
    const AirflowCoupling &coupling_;
    double time_;
    bool progress_;
    airflow::CouplingIteration iteration_;
    Eigen::VectorXd pressure_; // the sections' pressures the solid is being solved with
    AirflowStep result_;
  };

  // Solves the solid under the face pressures as set into `uAll` (every node's displacement, on
  // every rank); false: the solve failed (the coupling stops there).
  using SolidSolve = std::function<bool(std::vector<double> &uAll)>;

  // The step to `time` coupled around whole solid solves, from the starting state's displacement
  // `uStart`. `progress`: a line per coupling iteration. Collective through `solve`.
  AirflowStep couple(double time, const std::vector<double> &uStart, const SolidSolve &solve, bool progress,
                     const StepCoupling::SectionResponses &responses = {}) const;

  // Sets the airflow load's face pressures to 1 Pa on each section in turn and none elsewhere,
  // calls `visit(section)` for each, then puts back the pressures they had (the solid's
  // response to one section's pressure, for Newton's method).
  void forEachUnitSectionPressure(const std::function<void(std::size_t)> &visit) const;

  // The flow through the lumen at `uAll` under the drive at `time`, uncoupled (the t = 0 record,
  // and a controlled step's winner, solved among other candidates).
  AirflowStep flowAt(double time, const std::vector<double> &uAll) const;
  // Sets the airflow load's face pressures from the sections' (a controlled step's winner's, for
  // its output fields).
  void showPressures(const std::vector<double> &sectionPressure) const;

  const input::AirflowParameters &parameters() const { return parameters_; }
  std::size_t numSections() const { return flow_.numSections(); }

private:
  // Sets the airflow load's face pressures from the sections'.
  void setFacePressures(const Eigen::VectorXd &sectionPressure) const;
  airflow::FlowDrive drive(double time) const;
  airflow::AirwayFlowState measure(double time, const std::vector<double> &uAll) const;
  // dF/dp of the coupling's map at the solved state `uAll` whose flow gave `image`: column i the
  // flow's pressures through the lumen moved by a small multiple of `responses[i]`
  // (airway/ResponseProbe), less `image`, per pascal. A probe the flow cannot pass leaves its
  // column zero.
  Eigen::MatrixXd mapJacobian(double time, const std::vector<double> &uAll, const Eigen::VectorXd &image,
                              const std::vector<std::vector<double>> &responses) const;

  input::AirflowParameters parameters_;
  std::shared_ptr<const model::AirwayOutput> airway_;
  const model::Scene &scene_;
  airflow::AirwayFlow flow_;
  std::shared_ptr<std::vector<std::array<double, 4>>> facePressures_; // the airflow load's
};

} // namespace glossa::solvers
