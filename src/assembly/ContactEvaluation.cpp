#include "assembly/ContactEvaluation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "contact/DeformablePair.hpp"
#include "contact/FaceContact.hpp"
#include "contact/PairContact.hpp"
#include "loads/FaceShape.hpp"

namespace glossa::assembly {

namespace {

void evaluateRigid(const LoadTarget &target, const model::RigidContact &contact,
                   const ContactPointVisitor *visit) {
  const contact::FaceMultipliers none{0.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < contact.faces.size(); ++i) {
    const mesh::ElementFace &face = contact.faces[i];
    if (target.layout.elementOwner[face.element] != target.layout.rank) continue;
    const FaceAtTarget f = faceAt(target, face);
    const contact::FaceMultipliers lambda =
        contact.augmented() && contact.state ? contact.state->trialMultipliers(i) : none;
    contact::FaceContactPoints points;
    contact::FaceAnchors anchors;
    if (contact.state) anchors = contact.state->committedAnchors(i);
    const bool tangent = target.residual && target.K;
    loads::FaceTangent Kf;  // filled, and read, only with a tangent
    const loads::FaceForces ff =
        contact::faceContactForces(*contact.obstacle, f.X, f.u, lambda, contact.settings, &points,
                                   tangent ? &Kf : nullptr, contact.state ? &anchors : nullptr);
    if (visit)
      for (std::size_t q = 0; q < points.size(); ++q) (*visit)(i, q, points[q]);
    if (target.residual) target.subtract(f.nodes.data(), 4, ff.data(), tangent ? Kf.data() : nullptr);
  }
}

void evaluatePair(const LoadTarget &target, const model::RigidContact &contact,
                  const ContactPointVisitor *visit) {
  const contact::DeformablePair &pair = *contact.pair;
  const auto masterAt = [&](std::uint32_t m) { return faceAt(target, pair.masterFaces[m]).current(); };
  const bool tangent = target.residual && target.K;
  for (std::size_t i = 0; i < contact.faces.size(); ++i) {
    if (target.layout.elementOwner[contact.faces[i].element] != target.layout.rank) continue;
    const FaceAtTarget slave = faceAt(target, contact.faces[i]);
    const loads::FaceNodes xs = slave.current();
    const std::vector<contact::SlavePoint> &points = pair.points[i];
    for (std::size_t q = 0; q < points.size(); ++q) {
      const loads::FaceShape sh = loads::faceShape(points[q].st(0), points[q].st(1));
      const Eigen::Vector3d x = xs.transpose() * sh.N;
      const Eigen::Vector3d slaveNormal =
          (xs.transpose() * sh.dNds).cross(xs.transpose() * sh.dNdt).normalized();
      const auto match = contact::closestMasterFace(x, slaveNormal, pair.candidates[i], masterAt,
                                                    contact.settings.searchRadius);
      const double lambda = contact.augmented() && contact.state ? contact.state->trialMultiplier(i, q) : 0.0;
      contact::ContactPointState state;
      state.gap = std::numeric_limits<double>::infinity();
      if (!match || points[q].weight == 0.0) {  // a padding point carries nothing
        if (visit) (*visit)(i, q, state);
        continue;
      }
      const FaceAtTarget master = faceAt(target, pair.masterFaces[match->master]);
      contact::PairTangent K;  // filled, and read, only with a tangent
      const contact::PairForces f = contact::pairPointForces(
          xs, points[q], master.current(), lambda, contact.settings.penalty, &state, tangent ? &K : nullptr);
      if (visit) (*visit)(i, q, state);
      // A point apart (lambda - eps g < 0) gives nothing; at the kink it gives its tangent.
      if (!target.residual || lambda - contact.settings.penalty * state.gap < 0.0) continue;
      std::array<mesh::NodeId, 8> nodes{};
      std::copy(slave.nodes.begin(), slave.nodes.end(), nodes.begin());
      std::copy(master.nodes.begin(), master.nodes.end(), nodes.begin() + 4);
      target.subtract(nodes.data(), 8, f.data(), tangent ? K.data() : nullptr);
    }
  }
}

}  // namespace

void evaluateContact(const LoadTarget &target, const model::RigidContact &contact,
                     const ContactPointVisitor *visit) {
  if (contact.pair)
    evaluatePair(target, contact, visit);
  else
    evaluateRigid(target, contact, visit);
}

int nearestFaceNode(const model::RigidContact &contact, std::size_t face, std::size_t q) {
  if (!contact.pair) return static_cast<int>(q);
  // Node a sits at s = (-1, 1, 1, -1)[a], t = (-1, -1, 1, 1)[a]; a point on a midline goes to the
  // side of larger s or t.
  const Eigen::Vector2d &st = contact.pair->points[face][q].st;
  const bool sPlus = st(0) >= 0.0, tPlus = st(1) >= 0.0;
  return tPlus ? (sPlus ? 2 : 3) : (sPlus ? 1 : 0);
}

}  // namespace glossa::assembly
