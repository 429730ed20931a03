#include "solvers/run/StepRecorder.hpp"

#include <limits>

#include "assembly/ContactResponse.hpp"
#include "contact/DeformablePair.hpp"
#include "model/Scene.hpp"
#include "io/output/OutputError.hpp"
#include "materials/ActivationDynamics.hpp"
#include "solvers/run/Inertia.hpp"

namespace glossa::solvers {

StepRecorder::StepRecorder(const assembly::ResultEvaluator &results, const std::filesystem::path &dir, bool fields,
                           bool writer, std::vector<std::string> resultantSets, std::vector<std::string> volumeSets,
                           const OutputMark *resume, bool dynamic, std::shared_ptr<const model::AirwayOutput> airway)
    : evaluator_(results), root_(writer), fields_(fields), airwayModel_(std::move(airway)),
      resultantSets_(std::move(resultantSets)), volumeSets_(std::move(volumeSets)) {
  if (!root_) return;
  // A restart's files are kept and cut back to the checkpoint's lengths.
  auto resumeAt = [&](const char *file) -> std::optional<std::uintmax_t> {
    if (!resume) return std::nullopt;
    const auto at = resume->csvBytes.find(file);
    if (at == resume->csvBytes.end()) throw io::OutputError(std::string("the checkpoint does not record ") + file);
    return at->second;
  };
  if (!resultantSets_.empty())
    resultants_ = std::make_unique<io::KeyedCsvWriter>(dir / "resultants.csv", "face_set",
                                                       std::vector<std::string>{"fx [N]", "fy [N]", "fz [N]"},
                                                       resumeAt("resultants.csv"));
  if (!volumeSets_.empty())
    volumes_ = std::make_unique<io::KeyedCsvWriter>(dir / "volumes.csv", "face_set",
                                                    std::vector<std::string>{"volume [m^3]"}, resumeAt("volumes.csv"));
  if (!results.scene().contacts.empty())
    contacts_ = std::make_unique<io::KeyedCsvWriter>(
        dir / "contact.csv", "contact",
        std::vector<std::string>{"area [m^2]", "normal_force [N]", "largest_penetration [m]", "active_points [-]",
                                 "largest_gap_error [m]", "tangential_force [N]"},
        resumeAt("contact.csv"));
  if (airwayModel_) airway_ = std::make_unique<AirwayRecorder>(*airwayModel_, dir, resumeAt("airway.csv"));
  if (airwayModel_ && results.scene().airflowLoad >= 0) {
    std::vector<std::string> columns{"flow_rate [m^3/s]", "nasal_pressure [Pa]", "tracheal_pressure [Pa]",
                                     "smallest_area [m^2]", "smallest_section [-]", "closed [-]", "choked [-]",
                                     "coupling_iterations [-]", "coupling_change [Pa]"};
    for (std::size_t k = 0; k < airwayModel_->lumen->numSections(); ++k)
      columns.push_back("pressure_" + std::string(k < 10 ? "0" : "") + std::to_string(k) + " [Pa]");
    airflow_ = std::make_unique<io::KeyedCsvWriter>(dir / "airflow.csv", "airway", columns, resumeAt("airflow.csv"));
  }
  if (dynamic)
    energy_ = std::make_unique<io::KeyedCsvWriter>(
        dir / "energy.csv", "body",
        std::vector<std::string>{"kinetic_energy [J]", "strain_energy [J]", "total_energy [J]"}, resumeAt("energy.csv"));
  const auto &mesh = results.scene().mesh;
  if (fields_ && resume)
    results_ = std::make_unique<io::ResultWriter>(dir, "results", mesh.numNodes(), mesh.numElements(), resume->fieldSteps);
  else if (fields_)
    results_ = std::make_unique<io::ResultWriter>(dir, "results", mesh.nodes, mesh.elements);
  traces_ = std::make_unique<io::TraceWriter>(dir / "traces.csv", resumeAt("traces.csv"));
  // Reference fibre directions per family (zero where the family is absent), for ParaView's
  // glyphs; they do not change, and the mesh is replicated, so rank 0 builds them once.
  const auto &muscles = results.scene().muscles;
  const std::size_t elements = mesh.numElements();
  for (const auto &region : muscles.regions)
    for (const auto &name : region.familyNames) fibreDirections_.try_emplace(name, 3 * elements, 0.0);
  // Muscle sets (1 where an element carries a family of the group) for ParaView's threshold
  // filter, and with them the FFMR field per group written every step.
  for (const auto &g : muscles.groups) groupMembership_.emplace_back(g.name, std::vector<double>(elements, 0.0));
  for (std::size_t e = 0; e < elements && muscles.hasFibres(); ++e) {
    const int r = muscles.elementRegion[e];
    if (r < 0) continue;
    for (int g : muscles.regions[r].familyGroup)
      if (g >= 0) groupMembership_[g].second[e] = 1.0;
    for (std::size_t f = 0; f < muscles.regions[r].familyNames.size(); ++f)
      for (int c = 0; c < 3; ++c)
        fibreDirections_[muscles.regions[r].familyNames[f]][3 * e + c] =
            muscles.directions[e](c, static_cast<Eigen::Index>(f));
  }
  if (!results.scene().dirichlet.empty())
    reactions_ = std::make_unique<io::KeyedCsvWriter>(dir / "reactions.csv", "condition",
                                                      std::vector<std::string>{"fx [N]", "fy [N]", "fz [N]", "power [W]"},
                                                      resumeAt("reactions.csv"));
  if (!results.scene().muscles.groups.empty())
    activation_ = std::make_unique<io::KeyedCsvWriter>(
        dir / "activation.csv", "group",
        std::vector<std::string>{"u [-]", "alpha [-]", "ffmr [-]", "mean_fibre_stretch [-]", "mean_contractile_stretch [-]"},
        resumeAt("activation.csv"));
}

OutputMark StepRecorder::mark() const {
  OutputMark m;
  if (!root_) return m;
  m.csvBytes["traces.csv"] = traces_->bytes();
  for (const auto *csv : {resultants_.get(), volumes_.get(), reactions_.get(), activation_.get(), contacts_.get(),
                          energy_.get(), airflow_.get()})
    if (csv) m.csvBytes[csv->file().filename().string()] = csv->bytes();
  if (airway_) m.csvBytes["airway.csv"] = airway_->csv().bytes();
  if (results_) m.fieldSteps = results_->steps();
  return m;
}

std::vector<std::pair<std::string, Eigen::Vector3d>> StepRecorder::pointDisplacements(const std::vector<double> &u) const {
  std::vector<std::pair<std::string, Eigen::Vector3d>> out;
  const auto &mesh = evaluator_.scene().mesh;
  for (const auto &name : evaluator_.scene().tracedPoints) {
    out.emplace_back(name, mesh.namedPoints.at(name).interpolate(u));
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> StepRecorder::activationRows(const assembly::MuscleFields &muscle,
                                                                        const std::vector<double> &input) const {
  const auto &groups = evaluator_.scene().muscles.groups;
  const auto &alpha = evaluator_.muscleHistory().trialActivation();
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  for (std::size_t g = 0; g < groups.size(); ++g)
    rows.push_back({groups[g].name,
                    {input[g], alpha[g], materials::fractionOfFullMuscleResponse(groups[g].T0s, alpha[g]),
                     muscle.groupMeanStretch[g], muscle.groupMeanContractileStretch[g]}});
  return rows;
}

std::vector<std::pair<std::string, std::vector<double>>> StepRecorder::reactionRows(const assembly::Vector &u, double time,
                                                                      const std::vector<double> &lambda) const {
  const auto reactions = evaluator_.reactions(u, time, lambda);
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  for (std::size_t b = 0; b < reactions.size(); ++b) {
    const Eigen::Vector3d &f = reactions[b].force;
    rows.push_back({evaluator_.scene().dirichlet[b].name, {f.x(), f.y(), f.z(), reactions[b].power}});
  }
  return rows;
}

void StepRecorder::recordContacts(double time, const std::vector<contact::ContactMeasures> &contacts) {
  const auto &scene = evaluator_.scene();
  if (!root_ || !contacts_ || contacts.size() != scene.contacts.size()) return;
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const contact::ContactMeasures &m = contacts[c];
    rows.push_back({scene.contacts[c].name,
                    {m.area, m.normalForce, m.largestPenetration, static_cast<double>(m.activePoints), m.largestGapError,
                     m.tangentialForce}});
  }
  contacts_->append(time, rows);
}

void StepRecorder::recordAirway(double time, const std::vector<contact::ContactMeasures> &contacts) {
  if (root_ && airway_) airway_->record(time, airwayPositions_, contacts);
}

void StepRecorder::recordAirflow(double time, const AirflowStep &airflow) {
  if (!root_ || !airflow_ || !airflow.on) return;
  std::vector<double> row{airflow.flowRate,
                          airflow.nasalPressure,
                          airflow.trachealPressure,
                          airflow.smallestArea,
                          static_cast<double>(airflow.smallestSection),
                          airflow.closed ? 1.0 : 0.0,
                          airflow.choked ? 1.0 : 0.0,
                          static_cast<double>(airflow.iterations),
                          airflow.residual};
  row.insert(row.end(), airflow.sectionPressure.begin(), airflow.sectionPressure.end());
  row.resize(9 + airwayModel_->lumen->numSections(), std::numeric_limits<double>::quiet_NaN());
  airflow_->append(time, {{"airway", row}});
}

void StepRecorder::recordEnergy(double time, const StepEnergy &energy) {
  if (root_ && energy_) energy_->append(time, {{"all", {energy.kinetic, energy.stored, energy.total()}}});
}

namespace {
// The airflow's pressure at every node: the mean over the airway faces at the node of each face's
// mean Gauss-point pressure, as last set (the converged step's); 0 off the airway faces. Every
// rank holds every face's pressures.
std::vector<double> airflowNodePressure(const model::Scene &scene) {
  const model::FollowerPressureLoad &load = scene.pressures[static_cast<std::size_t>(scene.airflowLoad)];
  std::vector<double> sum(scene.mesh.numNodes(), 0.0), count(scene.mesh.numNodes(), 0.0);
  for (std::size_t k = 0; k < load.faces.size(); ++k) {
    const auto &p = (*load.given)[k];
    const double mean = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    for (const auto n : contact::faceNodeIds(scene.mesh, load.faces[k])) {
      sum[static_cast<std::size_t>(n)] += mean;
      count[static_cast<std::size_t>(n)] += 1.0;
    }
  }
  for (std::size_t n = 0; n < sum.size(); ++n)
    if (count[n] > 0.0) sum[n] /= count[n];
  return sum;
}
} // namespace

std::vector<io::Field> StepRecorder::nodeFields(const std::vector<double> &uAll) const {
  std::vector<io::Field> fields{{"displacement", 3, uAll}};
  if (inertia_) { // collective gathers
    fields.push_back({"velocity", 3, evaluator_.gatherDisplacement(inertia_->velocity())});
    fields.push_back({"acceleration", 3, evaluator_.gatherDisplacement(inertia_->acceleration())});
  }
  if (evaluator_.scene().airflowLoad >= 0)
    fields.push_back({"airflow_pressure", 1, airflowNodePressure(evaluator_.scene())});
  if (evaluator_.scene().contacts.empty()) return fields;
  // Collective; as the Uzawa loop's last solve recorded them at this state.
  assembly::ContactNodeFields contact = assembly::contactNodeFields(evaluator_);
  fields.push_back({"contact_pressure", 1, std::move(contact.pressure)});
  fields.push_back({"contact_gap", 1, std::move(contact.gap)});
  fields.push_back({"contact_slip", 1, std::move(contact.slip)});
  return fields;
}

std::vector<std::pair<std::string, std::vector<double>>> StepRecorder::record(double time, const assembly::Vector &u,
                                                                const std::vector<double> &lambda, bool writeFields,
                                                                const assembly::MuscleFields &muscle,
                                                                const std::vector<double> &input,
                                                                std::optional<double> fieldsTime) {
  const std::vector<double> uAll = evaluator_.gatherDisplacement(u);
  const auto reactions = reactionRows(u, time, lambda);
  if (root_) {
    std::vector<io::TraceWriter::Point> points;
    const auto &mesh = evaluator_.scene().mesh;
    for (const auto &[name, d] : pointDisplacements(uAll)) {
      const mesh::NamedPoint &p = mesh.namedPoints.at(name);
      // d from the imaged position: of the node, or interpolated like the displacement.
      Eigen::Vector3d offset = mesh.nodes[p.node] - mesh.imagedPosition(p.node);
      if (p.probe()) {
        offset.setZero();
        for (const auto &[n, w] : p.weights) offset += w * (mesh.nodes[n] - mesh.imagedPosition(n));
      }
      points.push_back({name, d, offset + d});
    }
    traces_->appendPoints(time, points);
  }
  if (root_ && reactions_) reactions_->append(time, reactions);
  if (root_ && airway_) airwayPositions_ = airwayModel_->positions(evaluator_.scene().mesh, uAll);
  // Collective, so every rank computes them; rank 0 writes.
  if (!resultantSets_.empty()) {
    const auto forces = evaluator_.faceSetResultants(u, time, lambda, resultantSets_);
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    for (std::size_t s = 0; s < forces.size(); ++s) rows.push_back({resultantSets_[s], {forces[s].x(), forces[s].y(), forces[s].z()}});
    if (root_) resultants_->append(time, rows);
  }
  if (!volumeSets_.empty()) {
    const auto volumes = evaluator_.enclosedVolumes(u, volumeSets_);
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    for (std::size_t s = 0; s < volumes.size(); ++s) rows.push_back({volumeSets_[s], {volumes[s]}});
    if (root_) volumes_->append(time, rows);
  }
  if (root_ && activation_) activation_->append(time, activationRows(muscle, input));
  if (!fields_ || !writeFields) return reactions;
  const auto f = evaluator_.elementFields(u, lambda);
  std::vector<double> stress;
  for (const auto &s : f.cauchy)
    for (double v : {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)}) stress.push_back(v);
  auto pressure = evaluator_.gatherElementField(f.pressure, 1);
  auto theta = evaluator_.gatherElementField(f.theta, 1);
  auto minJ = evaluator_.gatherElementField(f.minJ, 1);
  auto cauchy = evaluator_.gatherElementField(stress, 6);
  std::vector<io::Field> cells{
      {"pressure", 1, pressure}, {"dilatation", 1, theta}, {"J", 1, minJ}, {"cauchy_stress", 6, cauchy}};
  if (evaluator_.scene().muscles.hasFibres()) {
    cells.push_back({"fibre_stress", 1, evaluator_.gatherElementField(muscle.fibreStress, 1)});
    for (const auto &[name, values] : fibreDirections_) cells.push_back({"fibre_direction_" + name, 3, values});
    const auto &alpha = evaluator_.muscleHistory().trialActivation();
    for (std::size_t g = 0; g < groupMembership_.size() && root_; ++g) {
      const auto &[name, member] = groupMembership_[g];
      const double ffmr = materials::fractionOfFullMuscleResponse(evaluator_.scene().muscles.groups[g].T0s, alpha[g]);
      std::vector<double> field(member.size());
      for (std::size_t e = 0; e < member.size(); ++e) field[e] = member[e] * ffmr;
      cells.push_back({"muscle_set_" + name, 1, member});
      cells.push_back({"ffmr_" + name, 1, field});
    }
    // One column per group, gathered together and split by group on rank 0.
    const auto &groups = evaluator_.scene().muscles.groups;
    const int G = muscle.groups;
    const auto stretch = evaluator_.gatherElementField(muscle.fibreStretch, G);
    const auto contractile = evaluator_.gatherElementField(muscle.contractileStretch, G);
    for (int g = 0; g < G && root_; ++g) {
      std::vector<double> a, b;
      for (std::size_t e = 0; e < stretch.size() / static_cast<std::size_t>(G); ++e) {
        a.push_back(stretch[e * G + g]);
        b.push_back(contractile[e * G + g]);
      }
      cells.push_back({"fibre_stretch_" + groups[g].name, 1, a});
      cells.push_back({"contractile_stretch_" + groups[g].name, 1, b});
    }
  }
  const std::vector<io::Field> nodes = nodeFields(uAll);
  if (root_) results_->writeStep(fieldsTime.value_or(time), nodes, cells);
  return reactions;
}

} // namespace glossa::solvers
