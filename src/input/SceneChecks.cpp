#include "input/SceneChecks.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "contact/DeformablePair.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::input {

// The scene is the model layer's; this layer only reads it from the deck.
using namespace glossa::model;

namespace {
// "81, 82, 83" or "4, 9, 17, 23, 30 and 115 more".
template <class List, class Show>
std::string firstOf(const List &items, Show show) {
  std::ostringstream s;
  for (std::size_t i = 0; i < items.size() && i < 5; ++i) s << (i ? ", " : "") << show(items[i]);
  if (items.size() > 5) s << " and " << items.size() - 5 << " more";
  return s.str();
}

std::string vectorText(const Eigen::Vector3d &v) {
  std::ostringstream s;
  s.precision(3);
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

// The rigid-body motions of `part` that no constraint holds, in words; "" if none. Each fixed
// component c of a node at x holds the motions m with m(x) . e_c != 0; an external muscle's node
// holds those along its line of action. Translations and rotations about the part's centroid
// (scaled by its size) are the six motions; a free one is a null vector of the constraint rows.
std::string freeMotion(const std::vector<Eigen::Vector3d> &positions, const std::vector<Eigen::Vector3d> &directions,
                       const Eigen::Vector3d &centroid, double size) {
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Vector3d r = (positions[i] - centroid) / size;
    const Eigen::Vector3d &d = directions[i];
    Eigen::Matrix<double, 6, 1> row;
    row << d, r.cross(d); // d . (t + w x r) = d . t + w . (r x d)
    normal += row * row.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(normal);
  const double largest = std::max(eigen.eigenvalues()(5), 1.0);
  int free = 0;
  while (free < 6 && eigen.eigenvalues()(free) <= 1e-10 * largest) ++free;
  if (free == 6) return "move as a rigid body in every direction";
  std::string out;
  for (int k = 0; k < free; ++k) {
    const Eigen::Matrix<double, 6, 1> v = eigen.eigenvectors().col(k);
    const Eigen::Vector3d t = v.head<3>(), w = v.tail<3>();
    out += std::string(out.empty() ? "" : "; ") +
           (t.norm() >= w.norm() ? "translate along " + vectorText(t.normalized())
                                 : "rotate about the axis " + vectorText(w.normalized()) + " through its centroid");
  }
  return out;
}
// The directions the contacts hold nodes in, for the rigid-motion check. A rigid obstacle within its
// search radius of a contact face's node holds that node along its normal (one-sided, but
// supporting from Newton's first iteration: doc/contact.md). A deformable pair holds likewise: a
// node of either face set within the search radius of a face of the other holds along that face's
// normal (each body then rests on the other, which its own conditions hold).
void holdByContacts(const Scene &scene, const std::function<void(mesh::NodeId, const Eigen::Vector3d &)> &hold) {
  const mesh::HexMesh &m = scene.mesh;
  auto holdAgainst = [&](const std::vector<mesh::ElementFace> &from, const std::vector<mesh::ElementFace> &to,
                         double radius) {
    for (const mesh::ElementFace &face : from)
      for (mesh::NodeId n : contact::faceNodeIds(m, face))
        for (const mesh::ElementFace &other : to) {
          const auto nodes = contact::faceNodeIds(m, other);
          if (std::find(nodes.begin(), nodes.end(), n) != nodes.end()) continue;
          const loads::FaceNodes X = contact::referenceNodes(m, other);
          const Eigen::Vector3d x = m.nodes[static_cast<std::size_t>(n)];
          const Eigen::Vector3d lo = X.colwise().minCoeff().transpose(), hi = X.colwise().maxCoeff().transpose();
          if ((lo - x).cwiseMax(x - hi).cwiseMax(0.0).norm() > radius) continue; // cheap: the face's box
          const auto p = contact::projectOntoFace(X, x);
          if (p && p->inside && std::abs(p->gap) <= radius) hold(n, p->normal);
        }
  };
  for (const RigidContact &contact : scene.contacts) {
    if (contact.pair) {
      holdAgainst(contact.faces, contact.pair->masterFaces, contact.settings.searchRadius);
      holdAgainst(contact.pair->masterFaces, contact.faces, contact.settings.searchRadius);
      continue;
    }
    for (const mesh::ElementFace &face : contact.faces)
      for (mesh::NodeId n : contact::faceNodeIds(m, face))
        if (const auto cp = contact.obstacle->closest(m.nodes[static_cast<std::size_t>(n)], contact.settings.searchRadius))
          hold(n, cp->normal);
  }
}

} // namespace

void declareMeshCheckParameters(Teuchos::ParameterList &meshSection) {
  Teuchos::ParameterList &checks =
      meshSection.sublist("Checks", false, "what the mesh is checked for before a run (doc/meshes.md); duplicate "
                                           "elements, inverted corners and parts no condition holds are always refused");
  io::declareString(checks, "unused nodes", "refuse",
                    "nodes no element uses: refuse, or fix (held in place by a condition 'unused nodes'; they "
                    "carry no stiffness)",
                    {"refuse", "fix"});
  io::declareString(checks, "coincident nodes", "refuse",
                    "nodes closer than 1e-6 of the shortest element edge: refuse, or allow (the elements they "
                    "belong to stay unconnected there)",
                    {"refuse", "allow"});
}

void checkScene(const io::Deck &deck, Scene &scene) {
  const mesh::HexMesh &m = scene.mesh;
  const Teuchos::ParameterList &checks = deck.root().sublist("Mesh").sublist("Checks");
  // The mesh as its file gives it: a zero-strain configuration (Mesh/reference coordinates file)
  // is a computed deformation of it, checked at the Gauss points like any deformed state (the
  // tongue's, from gravity, turns two near-degenerate corners of the imaged mesh, scaled Jacobian
  // 0.0072, to -0.068 while det J stays positive at every Gauss point).
  mesh::HexMesh asRead;
  if (!m.imagedNodes.empty()) {
    asRead.elements = m.elements;
    asRead.nodes = m.imagedNodes;
  }
  const mesh::MeshCheckReport report = mesh::checkMesh(m.imagedNodes.empty() ? m : asRead);
  if (!m.imagedNodes.empty())
    for (std::size_t e = 0; e < m.numElements(); ++e)
      if (const double J = mesh::minGaussPointJacobian(m.elementCoordinates(static_cast<mesh::ElementId>(e)));
          !(J > 0.0)) {
        std::ostringstream s;
        s << deck.where({"Mesh", "reference coordinates file"}) << ": element " << e
          << " (0-based) is inverted in these coordinates: det(dX/dxi) = " << J << " at a Gauss point";
        throw io::DeckError(s.str());
      }
  const std::string at = deck.where({"Mesh"});
  auto node = [](mesh::NodeId n) { return std::to_string(n); };
  if (!report.duplicateElements.empty())
    throw io::DeckError(at + ": the mesh has " + std::to_string(report.duplicateElements.size()) +
                        " element(s) on the same eight nodes as another (elements, 0-based in the file's order: " +
                        firstOf(report.duplicateElements,
                                [](const auto &p) { return std::to_string(p.second) + " = " + std::to_string(p.first); }) +
                        "); remove the duplicates");
  if (!report.invertedCorners.empty())
    throw io::DeckError(at + ": the mesh has " + std::to_string(report.invertedCorners.size()) +
                        " element(s) with a corner whose scaled Jacobian is <= 0, inverted or degenerate (element: "
                        "smallest scaled Jacobian, 0-based in the file's order: " +
                        firstOf(report.invertedCorners,
                                [](const mesh::InvertedCorner &c) {
                                  std::ostringstream s;
                                  s.precision(3);
                                  s << c.element << ": " << c.scaledJacobian;
                                  return s.str();
                                }) +
                        "); fix the node order or the geometry (glossa mesh FILE shows the quality)");
  if (!report.coincidentNodes.empty() && checks.get<std::string>("coincident nodes") == "refuse")
    throw io::DeckError(at + ": the mesh has " + std::to_string(report.coincidentNodes.size()) +
                        " pair(s) of nodes at the same place (0-based, in the file's order: " +
                        firstOf(report.coincidentNodes,
                                [](const auto &p) { return std::to_string(p.first) + " = " + std::to_string(p.second); }) +
                        "), so the elements around them are not joined there; merge them, or set "
                        "Mesh/Checks/coincident nodes = allow if the gap is meant");
  if (!report.unusedNodes.empty()) {
    if (checks.get<std::string>("unused nodes") == "refuse")
      throw io::DeckError(at + ": the mesh has " + std::to_string(report.unusedNodes.size()) +
                          " node(s) that no element uses (0-based, in the file's order: " + firstOf(report.unusedNodes, node) +
                          "); they have no stiffness: remove them, or set Mesh/Checks/unused nodes = fix to hold "
                          "them in place");
    DirichletCondition hold;
    hold.name = "unused nodes";
    hold.nodes = report.unusedNodes;
    hold.fixed = {true, true, true};
    scene.dirichlet.push_back(std::move(hold));
  }

  // Rigid-body motions of each part: the constrained directions of its nodes.
  const auto [partOf, parts] = mesh::meshParts(m);
  std::vector<int> partOfNode(m.numNodes(), -1);
  std::vector<std::size_t> elementsOfPart(static_cast<std::size_t>(parts), 0);
  for (std::size_t e = 0; e < m.numElements(); ++e) {
    ++elementsOfPart[static_cast<std::size_t>(partOf[e])];
    for (mesh::NodeId n : m.elements[e]) partOfNode[static_cast<std::size_t>(n)] = partOf[e];
  }
  std::vector<std::vector<Eigen::Vector3d>> positions(static_cast<std::size_t>(parts)), directions(positions.size());
  auto hold = [&](mesh::NodeId n, const Eigen::Vector3d &d) {
    const int p = partOfNode[static_cast<std::size_t>(n)];
    if (p < 0) return;
    positions[static_cast<std::size_t>(p)].push_back(m.nodes[static_cast<std::size_t>(n)]);
    directions[static_cast<std::size_t>(p)].push_back(d);
  };
  for (const DirichletCondition &bc : scene.dirichlet)
    for (mesh::NodeId n : bc.nodes)
      for (int c = 0; c < 3; ++c)
        if (bc.fixed[c]) hold(n, Eigen::Vector3d::Unit(c));
  for (const ExternalMuscleGroup &muscle : scene.muscles.external)
    for (std::size_t i = 0; i < muscle.nodes.size(); ++i) {
      const Eigen::Vector3d line = muscle.fibres[i].origin - m.nodes[static_cast<std::size_t>(muscle.nodes[i])];
      if (line.norm() > 0.0) hold(muscle.nodes[i], line.normalized());
    }
  holdByContacts(scene, hold);
  for (int p = 0; p < parts; ++p) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    std::size_t count = 0;
    for (std::size_t n = 0; n < m.numNodes(); ++n)
      if (partOfNode[n] == p) {
        centroid += m.nodes[n];
        lo = lo.cwiseMin(m.nodes[n]);
        hi = hi.cwiseMax(m.nodes[n]);
        ++count;
      }
    centroid /= static_cast<double>(count);
    const double size = std::max((hi - lo).norm(), 1e-300);
    const std::string free = freeMotion(positions[static_cast<std::size_t>(p)], directions[static_cast<std::size_t>(p)],
                                        centroid, size);
    if (!free.empty())
      throw io::DeckError(deck.where({"Boundary conditions"}) + ": " +
                          (parts > 1 ? "part " + std::to_string(p + 1) + " of the mesh's " + std::to_string(parts) + " (" +
                                           std::to_string(elementsOfPart[static_cast<std::size_t>(p)]) +
                                           " element(s), centroid " + vectorText(centroid) + ")"
                                     : std::string("the body")) +
                          " is free to " + free +
                          ": no boundary condition holds it, so the system is singular; fix more components or add an "
                          "elastic support");
  }
}

} // namespace glossa::input
