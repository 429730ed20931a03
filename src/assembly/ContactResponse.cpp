#include "assembly/ContactResponse.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/ContactEvaluation.hpp"
#include "contact/DeformablePair.hpp"
#include "contact/FaceContact.hpp"
#include "io/deck/DeckError.hpp"

namespace glossa::assembly {

namespace {

// A deformable pair's faces can only meet their candidates (the graph's couplings) while no two
// of their nodes have moved apart by more than the pairing margin: a face outside a slave face's
// reach (search radius + margin) in the reference configuration then stays outside its search
// radius. The spread of the displacements over both face sets bounds every such relative motion;
// past the margin the run stops rather than miss a contact. Collective.
void checkPairingMargin(const model::RigidContact &contact, const LoadTarget &target, const Comm &comm) {
  const model::Scene &scene = target.scene;
  std::vector<double> lo(3, INFINITY), hi(3, -INFINITY);
  for (const auto *faces : {&contact.faces, &contact.pair->masterFaces})
    for (const mesh::ElementFace &face : *faces)
      for (mesh::NodeId n : contact::faceNodeIds(scene.mesh, face)) {
        if (target.layout.nodeOwner[n] != target.layout.rank) continue;
        const Eigen::Vector3d d = target.displacement(n);
        for (int c = 0; c < 3; ++c) {
          lo[c] = std::min(lo[c], d(c));
          hi[c] = std::max(hi[c], d(c));
        }
      }
  for (double &v : lo) v = -v; // one MAX reduction for both
  std::vector<double> local(lo), all(6);
  local.insert(local.end(), hi.begin(), hi.end());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 6, local.data(), all.data());
  const Eigen::Vector3d spread(all[3] + all[0], all[4] + all[1], all[5] + all[2]);
  if (spread.norm() <= contact.pair->margin) return;
  std::ostringstream os;
  os << "Contact/" << contact.name << ": the contact's faces have moved apart by up to " << spread.norm()
     << " m, more than its pairing margin (" << contact.pair->margin
     << " m): faces not paired when the matrix was built could now meet. Raise Contact/" << contact.name
     << "/pairing margin above the largest relative displacement expected";
  throw io::DeckError(os.str());
}

} // namespace

std::vector<ContactMeasures> updateContactStates(const ResultEvaluator &results, const Vector &u) {
  const model::Scene &scene = results.scene();
  const DistributedLayout &layout = results.assembler().layout();
  std::vector<ContactMeasures> out(scene.contacts.size());
  if (scene.contacts.empty()) return out;
  Vector uOverlap(results.overlapMap());
  results.importToOverlap(u, uOverlap);
  const LoadTarget target = results.loadTarget(uOverlap.getData(0), nullptr, nullptr, false);
  // Per contact: sums (area, normal force, active points, tangential force) and maxima
  // (penetration, gap error).
  constexpr std::size_t kSums = 4;
  std::vector<double> sums(kSums * out.size(), 0.0), maxima(2 * out.size(), 0.0);
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    const model::RigidContact &contact = scene.contacts[c];
    if (contact.pair) checkPairingMargin(contact, target, *layout.comm());
    const ContactPointVisitor record = [&](std::size_t face, std::size_t q, const contact::ContactPointState &p) {
      if (contact.state) contact.state->record(face, q, p);
      maxima[2 * c + 1] = std::max(maxima[2 * c + 1], contact::gapError(p));
      if (!p.active()) return;
      sums[kSums * c] += p.area;
      sums[kSums * c + 1] += p.pressure * p.area;
      sums[kSums * c + 2] += 1.0;
      sums[kSums * c + 3] += p.tangential * p.area;
      maxima[2 * c] = std::max(maxima[2 * c], -p.gap);
    };
    evaluateContact(target, contact, &record);
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
      for (std::size_t q = 0; q < contact.state->pointsPerFace(); ++q) {
        const int a = nearestFaceNode(contact, i, q);
        const auto node = static_cast<std::size_t>(scene.mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][a]]);
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
