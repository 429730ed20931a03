#include "assembly/Assembler.hpp"

#include "assembly/ZoltanPartition.hpp"

#include <algorithm>
#include <set>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Teuchos_CommHelpers.hpp>

#include "fem/HexShape.hpp"
#include "fem/Q1P0Element.hpp"
#include "loads/FollowerPressure.hpp"
#include "model/TissuePointLaw.hpp"

namespace glossa::assembly {

namespace {
Teuchos::RCP<const Map> makeMap(const std::vector<GlobalIndex> &gids, Tpetra::global_size_t total,
                                const Teuchos::RCP<const Comm> &comm) {
  Teuchos::Array<GO> ids(gids.begin(), gids.end());
  return Teuchos::rcp(new Map(total, ids(), 0, comm));
}
} // namespace

DofLayout distributeScene(const model::Scene &scene, const Teuchos::RCP<const Comm> &comm) {
  std::vector<int> owner;
  if (scene.partitioner != model::Partitioner::coordinateBisection && comm->getSize() > 1)
    owner = partitionElementsWithZoltan2(scene.mesh, comm,
                                         scene.partitioner == model::Partitioner::zoltan2Rcb ? "rcb" : "multijagged");
  return buildDofLayout(scene.mesh, comm->getRank(), comm->getSize(), std::move(owner));
}

Assembler::Assembler(const model::Scene &scene, DofLayout layout, const model::MuscleHistory &history,
                     Teuchos::RCP<const Comm> comm)
    : scene_(scene), comm_(std::move(comm)), layout_(std::move(layout)), history_(history) {
  const mesh::HexMesh &mesh = scene_.mesh;
  if (history_.numElements() != layout_.localElements.size())
    throw std::invalid_argument("Assembler: the muscle history has " + std::to_string(history_.numElements()) +
                                " elements, the layout " + std::to_string(layout_.localElements.size()) +
                                " local elements");
  ownedMap_ = makeMap(layout_.ownedDofs, layout_.numGlobalDofs(), comm_);
  overlapMap_ = makeMap(layout_.overlapDofs, Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), comm_);
  importer_ = Teuchos::rcp(new Import(ownedMap_, overlapMap_));
  pressureMap_ = makeMap(std::vector<GlobalIndex>(layout_.localElements.begin(), layout_.localElements.end()),
                         mesh.numElements(), comm_);
  exporter_ = Teuchos::rcp(new Export(overlapMap_, ownedMap_));

  constrained_.assign(3 * mesh.numNodes(), 0);
  for (const auto &bc : scene_.dirichlet)
    if (!bc.elastic())
      for (mesh::NodeId n : bc.nodes)
        for (int c = 0; c < 3; ++c)
          if (bc.fixed[c]) constrained_[3 * n + c] = 1;

  loads_ = loadContributions(scene_, history_, &externalMuscles_);

  nodeMultiplicity_.assign(mesh.numNodes(), 0);
  double volume = 0.0;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    for (mesh::NodeId n : mesh.elements[e]) ++nodeMultiplicity_[n];
    const fem::NodeMatrix X = mesh.elementCoordinates(static_cast<mesh::ElementId>(e));
    for (const auto &q : fem::gaussHex2()) {
      Eigen::Matrix<double, 8, 3> dNdX;
      double detJ = 0.0;
      if (!fem::hexGradients(X, q.xi, dNdX, detJ))
        throw std::runtime_error("mesh element " + std::to_string(e) +
                                 " has a non-positive Jacobian (inverted or degenerate)");
      volume += detJ * q.weight;
    }
  }
  // Dirichlet rows get a diagonal of the size of an element stiffness diagonal, so that they
  // neither dominate nor vanish in the preconditioner's spectrum.
  const double h = std::cbrt(volume / static_cast<double>(mesh.numElements()));
  // With several tissues: the stiffest one's (the same for every rank, whatever it owns).
  double stiffness = 0.0;
  for (const auto &t : scene_.tissues) stiffness = std::max(stiffness, t.volumetric.kappa() + 4.0 / 3.0 * t.matrix->shearModulus());
  dirichletScale_ = stiffness * h;

  elementLids_.resize(layout_.localElements.size());
  elementGids_.resize(layout_.localElements.size());
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    const auto &hex = mesh.elements[layout_.localElements[i]];
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c) {
        const GO gid = layout_.dof(hex[a], c);
        elementGids_[i][3 * a + c] = gid;
        elementLids_[i][3 * a + c] = overlapMap_->getLocalElement(gid);
      }
  }

  // Row capacity: 3 dofs per node coupled to the row's node through some element. 27 nodes on a
  // structured mesh, more where an unstructured mesh gathers more elements around a node.
  std::size_t maxNeighbours = 0;
  {
    std::vector<std::vector<mesh::NodeId>> neighbours(mesh.numNodes());
    for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
      const auto &hex = mesh.elements[layout_.localElements[i]];
      for (mesh::NodeId a : hex) neighbours[a].insert(neighbours[a].end(), hex.begin(), hex.end());
    }
    for (auto &n : neighbours) {
      std::sort(n.begin(), n.end());
      maxNeighbours = std::max(maxNeighbours, static_cast<std::size_t>(std::unique(n.begin(), n.end()) - n.begin()));
    }
  }
  graph_ = Teuchos::rcp(new FEGraph(ownedMap_, overlapMap_, 3 * maxNeighbours));
  graph_->beginAssembly();
  for (const auto &gids : elementGids_) {
    Teuchos::ArrayView<const GO> cols(gids.data(), 24);
    for (GO row : gids) graph_->insertGlobalIndices(row, cols);
  }
  graph_->endAssembly();
}

Teuchos::RCP<FEMatrix> Assembler::createMatrix() const { return Teuchos::rcp(new FEMatrix(graph_)); }

const ElementScatter &Assembler::elementScatter(const FEMatrix &K, const FEMatrix::local_matrix_host_type &local) const {
  // Every matrix of createMatrix shares graph_, so one set of offsets serves them all; a matrix
  // with another pattern (another graph) gets its own.
  const void *pattern = local.graph.entries.data();
  if (!scatter_ || scatterPattern_ != pattern) {
    const auto rowMap = K.getRowMap(), colMap = K.getColMap();
    std::vector<ElementScatter::Indices> rows(elementGids_.size()), cols(elementGids_.size());
    for (std::size_t i = 0; i < elementGids_.size(); ++i)
      for (int l = 0; l < 24; ++l) {
        rows[i][l] = rowMap->getLocalElement(elementGids_[i][l]);
        cols[i][l] = colMap->getLocalElement(elementGids_[i][l]);
      }
    scatter_ = std::make_shared<const ElementScatter>(local.graph.row_map.data(), local.graph.entries.data(),
                                                      static_cast<std::size_t>(local.numRows()), rows, cols);
    scatterPattern_ = pattern;
  }
  return *scatter_;
}

void Assembler::applyDirichlet(Vector &u, double time) const {
  for (const auto &bc : scene_.dirichlet) {
    if (bc.elastic()) continue;
    for (mesh::NodeId n : bc.nodes) {
      if (layout_.nodeOwner[n] != layout_.rank) continue;
      for (int c = 0; c < 3; ++c)
        if (bc.fixed[c]) u.replaceGlobalValue(layout_.dof(n, c), bc.prescribed(c, scene_.mesh.nodes[n], time));
    }
  }
}

void Assembler::zeroConstrainedDofs(Vector &v) const {
  // Owned dofs are contiguous and in the order of layout_.ownedNodes (3 per node).
  auto data = v.getDataNonConst(0);
  for (std::size_t k = 0; k < layout_.ownedNodes.size(); ++k)
    for (int c = 0; c < 3; ++c)
      if (constrained_[3 * layout_.ownedNodes[k] + c]) data[3 * k + c] = 0.0;
}

void Assembler::importToOverlap(const Vector &u, Vector &overlap) const {
  overlap.doImport(u, *importer_, Tpetra::INSERT);
}

fem::NodeMatrix Assembler::elementDisplacement(std::size_t i, const Teuchos::ArrayRCP<const double> &uData) const {
  fem::NodeMatrix ue;
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 3; ++c) ue(a, c) = uData[elementLids_[i][3 * a + c]];
  return ue;
}

PressureCoupling Assembler::pressureCoupling(const Vector &u) const {
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  const std::size_t n = layout_.localElements.size();
  PressureCoupling out;
  out.pressureMap = pressureMap_;
  out.volumeGradient = Teuchos::rcp(new CrsMatrix(pressureMap_, 24));
  out.referenceVolume.resize(n);
  out.currentVolume.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto e = layout_.localElements[i];
    fem::ElementVector g;
    if (!fem::elementVolumeGradient(scene_.mesh.elementCoordinates(e), elementDisplacement(i, uData),
                                    out.referenceVolume[i], out.currentVolume[i], g))
      g.setZero();
    const auto &hex = scene_.mesh.elements[e];
    for (int l = 0; l < 24; ++l)
      if (constrained_[3 * hex[l / 3] + l % 3]) g(l) = 0.0;
    out.volumeGradient->insertGlobalValues(static_cast<GO>(e), Teuchos::ArrayView<const GO>(elementGids_[i].data(), 24),
                                           Teuchos::ArrayView<const double>(g.data(), 24));
  }
  out.volumeGradient->fillComplete(ownedMap_, pressureMap_);
  return out;
}

std::vector<fem::MixedBase> Assembler::mixedBases(const Vector &u, const std::vector<double> &lambda,
                                                  const std::vector<fem::MixedBase> *previous) const {
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  std::vector<fem::MixedBase> bases(layout_.localElements.size());
  for (std::size_t i = 0; i < bases.size(); ++i)
    bases[i] = fem::mixedBase(scene_.mesh.elementCoordinates(layout_.localElements[i]), elementDisplacement(i, uData),
                              previous ? &(*previous)[i] : nullptr,
                              scene_.tissueOf(static_cast<std::size_t>(layout_.localElements[i])).volumetric, lambda[i]);
  return bases;
}

AssemblyStatus Assembler::assemble(const Vector &u, double time, const std::vector<double> &lambda,
                                   const std::vector<fem::MixedBase> *bases, Vector *f, FEMatrix *K,
                                   bool trialPoint) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector uOverlap(overlapMap_), fOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);

  double *values = nullptr;
  FEMatrix::local_matrix_host_type localK;
  if (K) {
    K->beginAssembly();
    K->setAllToScalar(0.0);
    localK = K->getLocalMatrixHost();
    values = localK.values.data();
  }
  const ElementScatter *scatter = K ? &elementScatter(*K, localK) : nullptr;
  int localValid = 1;
  double localMinJ = std::numeric_limits<double>::infinity(), localForceSquares = 0.0;
  const auto what = K ? fem::Q1P0Output::ResidualAndTangent : fem::Q1P0Output::ResidualOnly;
  {
    auto fData = fOverlap.getDataNonConst(0);
    for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
      const auto e = layout_.localElements[i];
      const auto &hex = mesh.elements[e];
      const fem::NodeMatrix X = mesh.elementCoordinates(e);
      const fem::NodeMatrix ue = elementDisplacement(i, uData);
      const fem::Q1P0Result r =
          evaluateElement(i, X, ue, lambda[i], bases ? &(*bases)[i] : nullptr, /*extrapolate=*/trialPoint, what);
      localMinJ = std::min(localMinJ, r.minJ);
      if (!r.valid) {
        localValid = 0;
        continue;
      }
      fem::ElementVector re = r.residual;
      localForceSquares += r.forceScale * r.forceScale;
      fem::ElementMatrix ke = r.tangent;
      for (int l = 0; l < 24; ++l) {
        if (!constrained_[3 * hex[l / 3] + l % 3]) continue;
        re(l) = 0.0;
        if (K) {
          ke.row(l).setZero();
          ke.col(l).setZero();
          ke(l, l) = dirichletScale_ / nodeMultiplicity_[hex[l / 3]];
        }
      }
      for (int l = 0; l < 24; ++l) fData[elementLids_[i][l]] += re(l);
      if (K) scatter->add(i, ke, values);
    }
    if (!addLoads(uData, time, fData, K, /*constrainedToo=*/false, everyLoad)) localValid = 0;
  }
  if (K) K->endAssembly();
  if (f) {
    f->putScalar(0.0);
    f->doExport(fOverlap, *exporter_, Tpetra::ADD);
  }
  AssemblyStatus status;
  int globalValid = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, localValid, Teuchos::outArg(globalValid));
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, localMinJ, Teuchos::outArg(status.minJ));
  double forceSquares = 0.0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, localForceSquares, Teuchos::outArg(forceSquares));
  status.forceScale = std::sqrt(forceSquares);
  status.valid = globalValid == 1;
  return status;
}

std::size_t Assembler::evaluateElementsOnly(const Vector &u, const std::vector<double> &lambda) const {
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  double sink = 0.0;
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    const auto r = evaluateElement(i, scene_.mesh.elementCoordinates(layout_.localElements[i]),
                                   elementDisplacement(i, uData), lambda[i], nullptr, false,
                                   fem::Q1P0Output::ResidualAndTangent);
    sink += r.tangent(0, 0) + r.residual(0); // kept, so that the kernel is not optimised away
  }
  volatile double keep = sink;
  (void)keep;
  return layout_.localElements.size();
}

ElementFields Assembler::elementFields(const Vector &u, const std::vector<double> &lambda) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  ElementFields out;
  const std::size_t n = layout_.localElements.size();
  out.theta.resize(n);
  out.pressure.resize(n);
  out.minJ.resize(n);
  out.cauchy.resize(n);
  out.referenceVolume.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto e = layout_.localElements[i];
    const fem::NodeMatrix ue = elementDisplacement(i, uData);
    const fem::NodeMatrix X = mesh.elementCoordinates(e);
    const auto r = evaluateElement(i, X, ue, lambda[i], nullptr, false, fem::Q1P0Output::ResidualOnly);
    out.theta[i] = r.theta;
    out.pressure[i] = r.pressure;
    out.minJ[i] = r.minJ;
    out.cauchy[i] = r.cauchyMean;
    out.referenceVolume[i] = r.referenceVolume;
  }
  return out;
}

Vector Assembler::loadResidual(const Vector &u, double time) const {
  Vector uOverlap(overlapMap_), fOverlap(overlapMap_), f(ownedMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  {
    auto fData = fOverlap.getDataNonConst(0);
    addLoads(uData, time, fData, nullptr, /*constrainedToo=*/false, everyLoad);
  }
  f.doExport(fOverlap, *exporter_, Tpetra::ADD);
  return f;
}

ElementFields Assembler::elementDilatations(const Vector &u, const std::vector<double> &lambda) const {
  if (scene_.formulation != model::ElementFormulation::Q1P0) return elementFields(u, lambda);
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  ElementFields out;
  const std::size_t n = layout_.localElements.size();
  out.theta.assign(n, 1.0);
  out.pressure.assign(n, 0.0);
  out.referenceVolume.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto e = layout_.localElements[i];
    double V = 0.0, v = 0.0;
    fem::ElementVector g;
    if (!fem::elementVolumeGradient(scene_.mesh.elementCoordinates(e), elementDisplacement(i, uData), V, v, g)) continue;
    out.theta[i] = v / V;
    out.pressure[i] = scene_.tissueOf(static_cast<std::size_t>(e)).volumetric.dU(out.theta[i]) + lambda[i];
    out.referenceVolume[i] = V;
  }
  return out;
}

Assembler::WorstCorner Assembler::worstCorner(const Vector &u) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr auto none = std::numeric_limits<mesh::ElementId>::max();
  std::array<std::pair<double, mesh::ElementId>, 2> local{{{inf, none}, {inf, none}}}; // all corners, regular ones
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    const auto e = layout_.localElements[i];
    const auto X = mesh.elementCoordinates(e);
    const auto ue = elementDisplacement(i, uData);
    const fem::CornerJacobians corners = fem::cornerJacobians(X, ue, kRegularCorner);
    const double J[2] = {corners.all, corners.regular};
    for (int k = 0; k < 2; ++k)
      if (J[k] < local[k].first || (J[k] == local[k].first && e < local[k].second)) local[k] = {J[k], e};
  }
  // The smallest over the ranks, and the lowest element id among equals.
  std::array<std::pair<double, mesh::ElementId>, 2> global{};
  for (int k = 0; k < 2; ++k) {
    double J = 0.0;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, local[k].first, Teuchos::outArg(J));
    const long long mine = local[k].first == J ? static_cast<long long>(local[k].second) : std::numeric_limits<long long>::max();
    long long element = 0;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(element));
    global[k] = {J, static_cast<mesh::ElementId>(element)};
  }
  return {global[0].first, global[0].second, global[1].first, global[1].second};
}

LoadTarget Assembler::loadTarget(const Teuchos::ArrayRCP<const double> &uData, Teuchos::ArrayRCP<double> *fData,
                                 FEMatrix *K, bool constrainedToo) const {
  return {scene_, layout_, *overlapMap_, constrained_, uData, fData, K, constrainedToo};
}

bool Assembler::addLoads(const Teuchos::ArrayRCP<const double> &uData, double time, Teuchos::ArrayRCP<double> &fData,
                         FEMatrix *K, bool constrainedToo,
                         const std::function<bool(const LoadContribution &)> &which) const {
  const LoadTarget target = loadTarget(uData, &fData, K, constrainedToo);
  bool valid = true;
  for (const auto &load : loads_)
    if (which(*load) && !load->addTo(target, time)) valid = false;
  return valid;
}

fem::Q1P0Result Assembler::evaluateElement(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue,
                                           double lambda, const fem::MixedBase *base, bool extrapolate,
                                           fem::Q1P0Output what) const {
  const auto e = static_cast<std::size_t>(layout_.localElements[i]);
  const int region = scene_.muscles.hasFibres() ? scene_.muscles.elementRegion[e] : -1;
  const model::Tissue &tissue = scene_.tissueOf(e);
  auto kernel = [&](const fem::QuadraturePointLaw &law) {
    if (scene_.formulation == model::ElementFormulation::PlainQ1)
      return fem::evaluatePlainQ1(X, ue, law, tissue.volumetric, what);
    if (base) return fem::evaluateQ1P0Mixed(X, ue, *base, law, tissue.volumetric, lambda, extrapolate, what);
    return fem::evaluateQ1P0(X, ue, law, tissue.volumetric, lambda, what);
  };
  if (region < 0) return kernel(fem::UniformPointLaw(*tissue.matrix));
  std::array<const double *, 8> lambdaCOld;
  std::array<double *, 8> lambdaCStart;
  for (int q = 0; q < 8; ++q) {
    lambdaCOld[q] = history_.committedLambdaC(i, q);
    lambdaCStart[q] = history_.lambdaCStart(i, q);
  }
  return kernel(model::TissuePointLaw(*scene_.muscles.regions[region].law, scene_.muscles.directions[e],
                                      history_.familyActivation(i), history_.dt(), lambdaCOld, nullptr,
                                      scene_.muscles.pointDirectionsOf(e), lambdaCStart));
}

Vector Assembler::nodalForces(const Teuchos::ArrayRCP<const double> &uData, double time,
                              const std::vector<double> &lambda, bool surfaceLoads) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector fOverlap(overlapMap_), f(ownedMap_);
  {
    auto fData = fOverlap.getDataNonConst(0);
    for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
      const auto r = evaluateElement(i, mesh.elementCoordinates(layout_.localElements[i]), elementDisplacement(i, uData),
                                     lambda[i], nullptr, false, fem::Q1P0Output::ResidualOnly);
      for (int l = 0; l < 24; ++l) fData[elementLids_[i][l]] += r.residual(l);
    }
    // The loads, not the supports' springs (their force is the reaction itself); surface loads
    // only when asked.
    addLoads(uData, time, fData, nullptr, /*constrainedToo=*/true, [surfaceLoads](const LoadContribution &l) {
      return l.kind() != LoadContribution::Kind::support && (surfaceLoads || !l.onSurface());
    });
  }
  f.doExport(fOverlap, *exporter_, Tpetra::ADD);
  return f;
}

std::vector<Reaction> Assembler::reactions(const Vector &u, double time, const std::vector<double> &lambda) const {
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  const Vector f = nodalForces(uData, time, lambda, /*surfaceLoads=*/true);
  auto fOwned = f.getData(0);
  // Per condition: the force (3) and its power (1), the sum of R . du/dt over its components.
  std::vector<double> local(4 * scene_.dirichlet.size(), 0.0), global(local.size(), 0.0);
  for (std::size_t b = 0; b < scene_.dirichlet.size(); ++b) {
    const auto &bc = scene_.dirichlet[b];
    for (mesh::NodeId n : bc.nodes) {
      if (layout_.nodeOwner[n] != layout_.rank) continue;
      for (int c = 0; c < 3; ++c) {
        if (!bc.fixed[c]) continue;
        double force = 0.0;
        if (!bc.elastic()) {
          force = fOwned[ownedMap_->getLocalElement(layout_.dof(n, c))];
        } else if (!constrained_[3 * n + c]) { // the spring's force on the body
          const double u = uData[overlapMap_->getLocalElement(layout_.dof(n, c))];
          force = -bc.nodeStiffness * (u - bc.prescribed(c, scene_.mesh.nodes[n], time));
        }
        local[4 * b + c] += force;
        if (force != 0.0) local[4 * b + 3] += force * bc.prescribedRate(c, scene_.mesh.nodes[n], time);
      }
    }
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  std::vector<Reaction> out;
  for (std::size_t b = 0; b < scene_.dirichlet.size(); ++b)
    out.push_back({Eigen::Vector3d(global[4 * b], global[4 * b + 1], global[4 * b + 2]), global[4 * b + 3]});
  return out;
}

std::vector<Eigen::Vector3d> Assembler::faceSetResultants(const Vector &u, double time, const std::vector<double> &lambda,
                                                         const std::vector<std::string> &faceSets) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  const Vector f = nodalForces(uOverlap.getData(0), time, lambda, /*surfaceLoads=*/false);
  auto fOwned = f.getData(0);
  std::vector<double> local(3 * faceSets.size(), 0.0), global(local.size(), 0.0);
  for (std::size_t s = 0; s < faceSets.size(); ++s) {
    std::set<mesh::NodeId> nodes;
    for (const auto &face : mesh.faceSets.at(faceSets[s]))
      for (int k = 0; k < 4; ++k) nodes.insert(mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][k]]);
    for (const mesh::NodeId n : nodes)
      if (layout_.nodeOwner[n] == layout_.rank)
        for (int c = 0; c < 3; ++c) local[3 * s + c] += fOwned[ownedMap_->getLocalElement(layout_.dof(n, c))];
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  std::vector<Eigen::Vector3d> out;
  for (std::size_t s = 0; s < faceSets.size(); ++s) out.emplace_back(global[3 * s], global[3 * s + 1], global[3 * s + 2]);
  return out;
}

std::vector<double> Assembler::enclosedVolumes(const Vector &u, const std::vector<std::string> &faceSets) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  Vector uOverlap(overlapMap_);
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  std::vector<double> local(faceSets.size(), 0.0), global(local.size(), 0.0);
  for (std::size_t s = 0; s < faceSets.size(); ++s)
    for (const auto &face : mesh.faceSets.at(faceSets[s])) {
      if (layout_.elementOwner[face.element] != layout_.rank) continue;
      loads::FaceNodes x; // the deformed face, its nodes in outward right-hand order
      for (int k = 0; k < 4; ++k) {
        const mesh::NodeId n = mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][k]];
        for (int c = 0; c < 3; ++c)
          x(k, c) = mesh.nodes[n](c) + uData[overlapMap_->getLocalElement(layout_.dof(n, c))];
      }
      local[s] += loads::faceVolumeMoment(x);
    }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

double Assembler::externalForceNorm(double time) const {
  Vector fOverlap(overlapMap_), f(ownedMap_);
  {
    auto fData = fOverlap.getDataNonConst(0);
    addLoads(Teuchos::ArrayRCP<const double>(), time, fData, nullptr, /*constrainedToo=*/false,
             [](const LoadContribution &l) { return l.kind() == LoadContribution::Kind::dead; });
  }
  f.doExport(fOverlap, *exporter_, Tpetra::ADD);
  return f.norm2();
}

Teuchos::RCP<MultiVector> Assembler::coordinates() const {
  Teuchos::Array<GO> nodeIds;
  for (mesh::NodeId n : layout_.ownedNodes) nodeIds.push_back(layout_.nodeNumber[n]);
  auto nodeMap = Teuchos::rcp(new Map(layout_.nodeNumber.size(), nodeIds(), 0, comm_));
  auto X = Teuchos::rcp(new MultiVector(nodeMap, 3));
  for (std::size_t i = 0; i < layout_.ownedNodes.size(); ++i)
    for (int c = 0; c < 3; ++c) X->replaceLocalValue(static_cast<LO>(i), c, scene_.mesh.nodes[layout_.ownedNodes[i]](c));
  return X;
}

Teuchos::RCP<MultiVector> Assembler::rigidBodyModes() const {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto &x : scene_.mesh.nodes) centre += x;
  centre /= static_cast<double>(scene_.mesh.numNodes());
  auto modes = Teuchos::rcp(new MultiVector(ownedMap_, 6));
  for (std::size_t i = 0; i < layout_.ownedNodes.size(); ++i) {
    const Eigen::Vector3d x = scene_.mesh.nodes[layout_.ownedNodes[i]] - centre;
    for (int c = 0; c < 3; ++c) {
      const LO lid = static_cast<LO>(3 * i + c);
      modes->replaceLocalValue(lid, c, 1.0);
      for (int r = 0; r < 3; ++r) {
        const Eigen::Vector3d w = Eigen::Vector3d::Unit(r).cross(x); // rotation about axis r
        modes->replaceLocalValue(lid, 3 + r, w(c));
      }
    }
  }
  return modes;
}

std::vector<double> Assembler::gatherDisplacement(const Vector &u) const {
  std::vector<double> local(3 * scene_.mesh.numNodes(), 0.0), global(local.size(), 0.0);
  auto data = u.getData(0);
  for (std::size_t i = 0; i < layout_.ownedNodes.size(); ++i)
    for (int c = 0; c < 3; ++c) local[3 * layout_.ownedNodes[i] + c] = data[3 * i + c];
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

void Assembler::scatterDisplacement(const std::vector<double> &all, Vector &u) const {
  if (all.size() != 3 * scene_.mesh.numNodes()) throw std::invalid_argument("scatterDisplacement: wrong size");
  auto data = u.getDataNonConst(0);
  for (std::size_t i = 0; i < layout_.ownedNodes.size(); ++i)
    for (int c = 0; c < 3; ++c) data[3 * i + c] = all[3 * layout_.ownedNodes[i] + c];
}

std::vector<double> Assembler::localElementValues(const std::vector<double> &all) const {
  if (all.size() != scene_.mesh.numElements()) throw std::invalid_argument("localElementValues: wrong size");
  std::vector<double> local(layout_.localElements.size());
  for (std::size_t i = 0; i < local.size(); ++i) local[i] = all[layout_.localElements[i]];
  return local;
}

std::vector<double> Assembler::gatherElementField(const std::vector<double> &values, int components) const {
  std::vector<double> local(components * scene_.mesh.numElements(), 0.0), global(local.size(), 0.0);
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i)
    for (int c = 0; c < components; ++c) local[components * layout_.localElements[i] + c] = values[components * i + c];
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

} // namespace glossa::assembly
