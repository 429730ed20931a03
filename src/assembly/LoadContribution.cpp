#include "assembly/LoadContribution.hpp"

#include <array>

#include "assembly/ContactEvaluation.hpp"
#include "contact/DeformablePair.hpp"
#include "loads/BodyForce.hpp"
#include "loads/DeadTraction.hpp"
#include "loads/ExternalMuscle.hpp"
#include "loads/FollowerPressure.hpp"

namespace glossa::assembly {

Eigen::Vector3d LoadTarget::displacement(mesh::NodeId node) const {
  Eigen::Vector3d d;
  for (int c = 0; c < 3; ++c) d(c) = u[overlapMap.getLocalElement(layout.dof(node, c))];
  return d;
}

void LoadTarget::subtract(const mesh::NodeId *nodes, int n, const double *f, const double *df) const {
  std::array<GO, 24> gids{};
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) gids[3 * k + c] = layout.dof(nodes[k], c);
  for (int r = 0; r < 3 * n; ++r) {
    const bool fixedRow = constrained[3 * nodes[r / 3] + r % 3];
    if (fixedRow && !constrainedToo) continue;
    (*residual)[overlapMap.getLocalElement(gids[r])] -= f[r];
    if (!K || !df || fixedRow) continue;
    std::array<double, 24> row{};
    for (int c = 0; c < 3 * n; ++c) row[c] = constrained[3 * nodes[c / 3] + c % 3] ? 0.0 : -df[r + 3 * n * c];
    K->sumIntoGlobalValues(gids[r], Teuchos::ArrayView<const GO>(gids.data(), 3 * n),
                           Teuchos::ArrayView<const double>(row.data(), 3 * n));
  }
}

FaceAtTarget faceAt(const LoadTarget &target, const mesh::ElementFace &face) {
  FaceAtTarget f{contact::faceNodeIds(target.scene.mesh, face), {}, {}};
  for (int k = 0; k < 4; ++k) {
    f.X.row(k) = target.scene.mesh.nodes[f.nodes[k]].transpose();
    f.u.row(k) = target.displacement(f.nodes[k]).transpose();
  }
  return f;
}

namespace {

// A traction per reference area on a face set, scaled in time (loads/DeadTraction).
class DeadTractionContribution final : public LoadContribution {
public:
  explicit DeadTractionContribution(const model::DeadTractionLoad &load) : load_(load) {}
  Kind kind() const override { return Kind::dead; }
  bool onSurface() const override { return true; }
  bool addTo(const LoadTarget &target, double time) const override {
    const mesh::HexMesh &mesh = target.scene.mesh;
    const Eigen::Vector3d t = load_.traction * load_.scale(time);
    for (const auto &face : load_.faces) {
      if (target.layout.elementOwner[face.element] != target.layout.rank) continue;
      const auto nodes = contact::faceNodeIds(mesh, face);
      loads::FaceNodes Xf;
      for (int k = 0; k < 4; ++k) Xf.row(k) = mesh.nodes[nodes[k]].transpose();
      const loads::FaceForces ff = loads::deadTractionForces(Xf, t);
      target.subtract(nodes.data(), 4, ff.data(), nullptr);
    }
    return true;
  }

private:
  const model::DeadTractionLoad &load_;
};

// rho a on an element set, rho each element's tissue's (loads/BodyForce): gravity and body forces.
class BodyForceContribution final : public LoadContribution {
public:
  explicit BodyForceContribution(const model::BodyForceLoad &load) : load_(load) {}
  Kind kind() const override { return Kind::dead; }
  bool onSurface() const override { return false; }
  bool addTo(const LoadTarget &target, double time) const override {
    const Eigen::Vector3d a = load_.scale(time) * load_.acceleration;
    if (a.isZero()) return true;
    const mesh::HexMesh &mesh = target.scene.mesh;
    for (const auto e : load_.elements) {
      if (target.layout.elementOwner[e] != target.layout.rank) continue;
      const Eigen::Vector3d b = target.scene.tissueOf(static_cast<std::size_t>(e)).density * a;
      const loads::HexForces fe = loads::bodyForces(mesh.elementCoordinates(e), b);
      target.subtract(mesh.elements[e].data(), 8, fe.data(), nullptr);
    }
    return true;
  }

private:
  const model::BodyForceLoad &load_;
};

// A pressure on the deformed faces of a face set, varying in space and time (loads/FollowerPressure).
class FollowerPressureContribution final : public LoadContribution {
public:
  explicit FollowerPressureContribution(const model::FollowerPressureLoad &load) : load_(load) {}
  Kind kind() const override { return Kind::follower; }
  bool onSurface() const override { return true; }
  bool addTo(const LoadTarget &target, double time) const override {
    for (std::size_t k = 0; k < load_.faces.size(); ++k) {
      const mesh::ElementFace &face = load_.faces[k];
      if (target.layout.elementOwner[face.element] != target.layout.rank) continue;
      const FaceAtTarget f = faceAt(target, face);
      loads::FaceTangent Kf; // filled, and read, only with a tangent
      const std::array<double, 4> p = load_.given ? (*load_.given)[k] : load_.pressure.atGaussPoints(f.X, time);
      const loads::FaceForces ff = loads::followerPressureForces(f.X, f.u, p, target.K ? &Kf : nullptr);
      target.subtract(f.nodes.data(), 4, ff.data(), target.K ? Kf.data() : nullptr);
    }
    return true;
  }

private:
  const model::FollowerPressureLoad &load_;
};

// The springs of an elastic support (DirichletCondition::elastic): the body feels -k (u - g), so
// the residual gains k (u - g) and the tangent k at every supported component of this rank's nodes.
class ElasticSupportContribution final : public LoadContribution {
public:
  explicit ElasticSupportContribution(const model::DirichletCondition &support) : support_(support) {}
  Kind kind() const override { return Kind::support; }
  bool onSurface() const override { return true; }
  bool addTo(const LoadTarget &target, double time) const override {
    const double k = support_.nodeStiffness;
    for (mesh::NodeId n : support_.nodes) {
      if (target.layout.nodeOwner[n] != target.layout.rank) continue;
      const Eigen::Vector3d u = target.displacement(n);
      Eigen::Vector3d f = Eigen::Vector3d::Zero();
      Eigen::Matrix3d df = Eigen::Matrix3d::Zero();
      for (int c = 0; c < 3; ++c) {
        if (!support_.fixed[c]) continue;
        f(c) = -k * (u(c) - support_.prescribed(c, target.scene.mesh.nodes[n], time));
        df(c, c) = -k;
      }
      target.subtract(&n, 1, f.data(), df.data());
    }
    return true;
  }

private:
  const model::DirichletCondition &support_;
};

// Contact of a face set with a rigid obstacle or another face set (assembly/ContactEvaluation): a
// follower load, the obstacle's push and friction on the faces that touch it, with the state's
// trial multipliers under the augmented Lagrangian (none for the penalty method) and its committed
// anchors. A moving obstacle is put where it is at the evaluation's time first.
class ContactContribution final : public LoadContribution {
public:
  explicit ContactContribution(const model::RigidContact &contact) : contact_(contact) {}
  Kind kind() const override { return Kind::follower; }
  bool onSurface() const override { return true; }
  bool addTo(const LoadTarget &target, double time) const override {
    if (contact_.motion) contact_.motion->setTime(time);
    evaluateContact(target, contact_, nullptr);
    return true;
  }

private:
  const model::RigidContact &contact_;
};

} // namespace

bool ExternalMuscleForces::addTo(const LoadTarget &target, double) const { return evaluate(target, nullptr, nullptr); }

bool ExternalMuscleForces::evaluate(const LoadTarget &target, model::MuscleHistory *trial,
                                    std::vector<double> *stretch) const {
  bool valid = true;
  for (std::size_t m = 0; m < scene_.muscles.external.size(); ++m) {
    const auto &muscle = scene_.muscles.external[m];
    const double alpha = history_.groupActivation(muscle.group);
    for (std::size_t k = 0; k < muscle.nodes.size(); ++k) {
      const mesh::NodeId node = muscle.nodes[k];
      if (target.layout.nodeOwner[node] != target.layout.rank) continue;
      const auto r = muscle.law->evaluate(muscle.fibres[k], target.displacement(node), alpha, history_.dt(),
                                          history_.committedExternalLambdaC(m, k));
      if (!materials::succeeded(r.hill.status) || !r.force.allFinite()) {
        valid = false;
        continue;
      }
      if (trial) trial->trialExternalLambdaC(m, k) = r.hill.lambdaC;
      if (stretch && muscle.group >= 0) {
        const double L0 = (muscle.fibres[k].origin - muscle.fibres[k].insertion).norm();
        (*stretch)[3 * muscle.group] += r.lambdaF * L0;
        (*stretch)[3 * muscle.group + 1] += r.hill.lambdaC * L0;
        (*stretch)[3 * muscle.group + 2] += L0;
      }
      if (target.residual) target.subtract(&node, 1, r.force.data(), r.dForceDu.data());
    }
  }
  return valid;
}

std::unique_ptr<LoadContribution> followerPressureContribution(const model::FollowerPressureLoad &load) {
  return std::make_unique<FollowerPressureContribution>(load);
}

std::vector<std::unique_ptr<LoadContribution>> loadContributions(const model::Scene &scene,
                                                                 const model::MuscleHistory &history,
                                                                 const ExternalMuscleForces **externalMuscles) {
  std::vector<std::unique_ptr<LoadContribution>> loads;
  for (const auto &load : scene.tractions) loads.push_back(std::make_unique<DeadTractionContribution>(load));
  for (const auto &load : scene.bodyForces) loads.push_back(std::make_unique<BodyForceContribution>(load));
  for (const auto &load : scene.pressures) loads.push_back(std::make_unique<FollowerPressureContribution>(load));
  for (const auto &contact : scene.contacts) loads.push_back(std::make_unique<ContactContribution>(contact));
  auto muscles = std::make_unique<ExternalMuscleForces>(scene, history);
  *externalMuscles = muscles.get();
  loads.push_back(std::move(muscles));
  for (const auto &bc : scene.dirichlet)
    if (bc.elastic()) loads.push_back(std::make_unique<ElasticSupportContribution>(bc));
  return loads;
}

} // namespace glossa::assembly
