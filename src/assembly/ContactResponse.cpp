#include "assembly/ContactResponse.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include "contact/FaceContact.hpp"

namespace glossa::assembly {

std::vector<ContactMeasures> updateContactStates(const ResultEvaluator &results, const Vector &u) {
  const model::Scene &scene = results.scene();
  const DistributedLayout &layout = results.assembler().layout();
  std::vector<ContactMeasures> out(scene.contacts.size());
  if (scene.contacts.empty()) return out;
  Vector uOverlap(results.overlapMap());
  results.importToOverlap(u, uOverlap);
  const auto uData = uOverlap.getData(0);
  const Map &overlap = *results.overlapMap();
  // Per contact: sums (area, normal force, active points, tangential force) and maxima
  // (penetration, gap error).
  constexpr std::size_t kSums = 4;
  std::vector<double> sums(kSums * out.size(), 0.0), maxima(2 * out.size(), 0.0);
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    const model::RigidContact &contact = scene.contacts[c];
    const contact::FaceMultipliers none{0.0, 0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < contact.faces.size(); ++i) {
      const mesh::ElementFace &face = contact.faces[i];
      if (layout.elementOwner[face.element] != layout.rank) continue;
      loads::FaceNodes X, d;
      for (int k = 0; k < 4; ++k) {
        const mesh::NodeId node = scene.mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][k]];
        X.row(k) = scene.mesh.nodes[node].transpose();
        for (int a = 0; a < 3; ++a) d(k, a) = uData[overlap.getLocalElement(layout.dof(node, a))];
      }
      const contact::FaceMultipliers lambda = contact.augmented() && contact.state ? contact.state->trialMultipliers(i) : none;
      contact::FaceContactPoints points;
      contact::FaceAnchors anchors;
      if (contact.state) anchors = contact.state->committedAnchors(i);
      contact::faceContactForces(*contact.obstacle, X, d, lambda, contact.settings, &points, nullptr,
                                 contact.state ? &anchors : nullptr);
      if (contact.state) contact.state->record(i, points);
      for (const contact::ContactPointState &p : points) {
        maxima[2 * c + 1] = std::max(maxima[2 * c + 1], contact::gapError(p));
        if (!p.active()) continue;
        sums[kSums * c] += p.area;
        sums[kSums * c + 1] += p.pressure * p.area;
        sums[kSums * c + 2] += 1.0;
        sums[kSums * c + 3] += p.tangential * p.area;
        maxima[2 * c] = std::max(maxima[2 * c], -p.gap);
      }
    }
  }
  std::vector<double> sumAll(sums.size()), maxAll(maxima.size());
  const Comm &comm = *layout.comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(), sumAll.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(maxima.size()), maxima.data(), maxAll.data());
  for (std::size_t c = 0; c < out.size(); ++c) {
    out[c].area = sumAll[kSums * c];
    out[c].normalForce = sumAll[kSums * c + 1];
    out[c].activePoints = static_cast<long>(sumAll[kSums * c + 2]);
    out[c].tangentialForce = sumAll[kSums * c + 3];
    out[c].largestPenetration = maxAll[2 * c];
    out[c].largestGapError = maxAll[2 * c + 1];
    out[c].augmented = scene.contacts[c].augmented();
    out[c].gapTolerance = scene.contacts[c].gapTolerance;
  }
  return out;
}

bool updateContactMultipliers(const model::Scene &scene, const std::vector<ContactMeasures> &measures) {
  bool updated = false;
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    const model::RigidContact &contact = scene.contacts[c];
    if (measures[c].gapMet() || !contact.state) continue;
    contact.state->updateMultipliers(contact.settings.penalty);
    updated = true;
  }
  return updated;
}

ContactNodeFields contactNodeFields(const ResultEvaluator &results) {
  const model::Scene &scene = results.scene();
  const DistributedLayout &layout = results.assembler().layout();
  const std::size_t nodes = scene.mesh.numNodes();
  // Per node: pressure sum, its count, finite gap sum, its count, slip sum.
  constexpr std::size_t kPer = 5;
  std::vector<double> local(kPer * nodes, 0.0), all(kPer * nodes, 0.0);
  for (const model::RigidContact &contact : scene.contacts) {
    if (!contact.state) continue;
    for (std::size_t i = 0; i < contact.faces.size(); ++i) {
      const mesh::ElementFace &face = contact.faces[i];
      if (layout.elementOwner[face.element] != layout.rank) continue;
      for (std::size_t q = 0; q < contact::ContactState::kPointsPerFace; ++q) {
        const auto node = static_cast<std::size_t>(scene.mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][q]]);
        const contact::ContactPointState point = contact.state->point(i, q);
        local[kPer * node] += point.pressure;
        local[kPer * node + 1] += 1.0;
        local[kPer * node + 4] += point.slip;
        if (!std::isfinite(point.gap)) continue;
        local[kPer * node + 2] += point.gap;
        local[kPer * node + 3] += 1.0;
      }
    }
  }
  Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), all.data());
  ContactNodeFields out{std::vector<double>(nodes, 0.0), std::vector<double>(nodes, std::nan("")),
                        std::vector<double>(nodes, 0.0)};
  for (std::size_t n = 0; n < nodes; ++n) {
    if (all[kPer * n + 1] > 0) out.pressure[n] = all[kPer * n] / all[kPer * n + 1];
    if (all[kPer * n + 1] > 0) out.slip[n] = all[kPer * n + 4] / all[kPer * n + 1];
    if (all[kPer * n + 3] > 0) out.gap[n] = all[kPer * n + 2] / all[kPer * n + 3];
  }
  return out;
}

} // namespace glossa::assembly
