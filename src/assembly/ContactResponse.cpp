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
  // Per contact: sums (area, force, active points) and maxima (penetration, gap error).
  std::vector<double> sums(3 * out.size(), 0.0), maxima(2 * out.size(), 0.0);
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
      contact::faceContactForces(*contact.obstacle, X, d, lambda, contact.settings, &points);
      if (contact.state) contact.state->record(i, points);
      for (const contact::ContactPointState &p : points) {
        maxima[2 * c + 1] = std::max(maxima[2 * c + 1], contact::gapError(p));
        if (!p.active()) continue;
        sums[3 * c] += p.area;
        sums[3 * c + 1] += p.pressure * p.area;
        sums[3 * c + 2] += 1.0;
        maxima[2 * c] = std::max(maxima[2 * c], -p.gap);
      }
    }
  }
  std::vector<double> sumAll(sums.size()), maxAll(maxima.size());
  const Comm &comm = *layout.comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(), sumAll.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(maxima.size()), maxima.data(), maxAll.data());
  for (std::size_t c = 0; c < out.size(); ++c) {
    out[c].area = sumAll[3 * c];
    out[c].normalForce = sumAll[3 * c + 1];
    out[c].activePoints = static_cast<long>(sumAll[3 * c + 2]);
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
  // Per node: pressure sum, its count, finite gap sum, its count.
  std::vector<double> local(4 * nodes, 0.0), all(4 * nodes, 0.0);
  for (const model::RigidContact &contact : scene.contacts) {
    if (!contact.state) continue;
    for (std::size_t i = 0; i < contact.faces.size(); ++i) {
      const mesh::ElementFace &face = contact.faces[i];
      if (layout.elementOwner[face.element] != layout.rank) continue;
      for (std::size_t q = 0; q < contact::ContactState::kPointsPerFace; ++q) {
        const auto node = static_cast<std::size_t>(scene.mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][q]]);
        const contact::ContactPointState point = contact.state->point(i, q);
        local[4 * node] += point.pressure;
        local[4 * node + 1] += 1.0;
        if (!std::isfinite(point.gap)) continue;
        local[4 * node + 2] += point.gap;
        local[4 * node + 3] += 1.0;
      }
    }
  }
  Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), all.data());
  ContactNodeFields out{std::vector<double>(nodes, 0.0), std::vector<double>(nodes, std::nan(""))};
  for (std::size_t n = 0; n < nodes; ++n) {
    if (all[4 * n + 1] > 0) out.pressure[n] = all[4 * n] / all[4 * n + 1];
    if (all[4 * n + 3] > 0) out.gap[n] = all[4 * n + 2] / all[4 * n + 3];
  }
  return out;
}

} // namespace glossa::assembly
