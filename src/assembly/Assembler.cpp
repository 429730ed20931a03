#include "assembly/Assembler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>

#include "fem/HexShape.hpp"
#include "fem/Q1P0Element.hpp"
#include "model/TissuePointLaw.hpp"

namespace glossa::assembly {

namespace {
// Which local elements keep their displacement parts: the muscle elements, unless none should.
std::vector<char> keptElements(const model::Scene &scene, const std::vector<mesh::ElementId> &localElements,
                               ElementParts parts) {
  std::vector<char> keeps(localElements.size(), 0);
  if (parts == ElementParts::Fresh || !scene.muscles.hasFibres()) return keeps;
  for (std::size_t i = 0; i < localElements.size(); ++i)
    keeps[i] = scene.muscles.elementRegion[static_cast<std::size_t>(localElements[i])] >= 0;
  return keeps;
}
} // namespace

Assembler::Assembler(const model::Scene &scene, DofLayout layout, const model::MuscleHistory &history,
                     Teuchos::RCP<const Comm> comm, const std::vector<materials::VolumetricEnergy> *tangentLaws,
                     ElementParts parts)
    : scene_(scene), layout_(std::move(layout), std::move(comm)), history_(history),
      parts_(keptElements(scene_, layout_.localElements, parts)), tangentLaws_(tangentLaws) {
  const mesh::HexMesh &mesh = scene_.mesh;
  if (tangentLaws_ && tangentLaws_->size() != scene_.tissues.size())
    throw std::invalid_argument("Assembler: " + std::to_string(tangentLaws_->size()) + " tangent laws for " +
                                std::to_string(scene_.tissues.size()) + " tissues");
  if (history_.numElements() != layout_.localElements.size())
    throw std::invalid_argument("Assembler: the muscle history has " + std::to_string(history_.numElements()) +
                                " elements, the layout " + std::to_string(layout_.localElements.size()) +
                                " local elements");
  const Teuchos::RCP<const Map> ownedMap = layout_.ownedMap(), overlapMap = layout_.overlapMap();
  importer_ = Teuchos::rcp(new Import(ownedMap, overlapMap));
  exporter_ = Teuchos::rcp(new Export(overlapMap, ownedMap));

  constrained_.assign(3 * mesh.numNodes(), 0);
  for (const auto &bc : scene_.dirichlet)
    if (!bc.elastic())
      for (mesh::NodeId n : bc.nodes)
        for (int c = 0; c < 3; ++c)
          if (bc.fixed[c]) constrained_[3 * n + c] = 1;
  // The constrained dofs this rank sees (owned and ghosted), in the conditions' order so that a
  // later condition on the same dof wins, as in applyDirichlet.
  for (std::size_t k = 0; k < scene_.dirichlet.size(); ++k) {
    const auto &bc = scene_.dirichlet[k];
    if (bc.elastic()) continue;
    for (mesh::NodeId n : bc.nodes)
      for (int c = 0; c < 3; ++c) {
        const LO lid = bc.fixed[c] ? overlapMap->getLocalElement(layout_.dof(n, c))
                                   : Teuchos::OrdinalTraits<LO>::invalid();
        if (lid != Teuchos::OrdinalTraits<LO>::invalid()) prescribedDofs_.push_back({lid, k, n, c});
      }
  }

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
  for (std::size_t t = 0; t < scene_.tissues.size(); ++t)
    stiffness = std::max(stiffness, (tangentLaws_ ? (*tangentLaws_)[t] : scene_.tissues[t].volumetric).kappa() +
                                        4.0 / 3.0 * scene_.tissues[t].matrix->shearModulus());
  dirichletScale_ = stiffness * h;

  elementLids_.resize(layout_.localElements.size());
  elementGids_.resize(layout_.localElements.size());
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    const auto &hex = mesh.elements[layout_.localElements[i]];
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c) {
        const GO gid = layout_.dof(hex[a], c);
        elementGids_[i][3 * a + c] = gid;
        elementLids_[i][3 * a + c] = overlapMap->getLocalElement(gid);
      }
  }

  // A deformable contact's slave faces of this rank couple their nodes with their candidate master
  // faces' (model::contactCouplings): the graph holds those entries from the start, since it is
  // built once; the search never pairs faces outside them (doc/contact.md).
  const std::vector<model::NodeCoupling> couplings = model::contactCouplings(scene_);
  std::vector<std::vector<GO>> couplingGids;
  for (const model::NodeCoupling &coupling : couplings) {
    if (layout_.elementOwner[coupling.element] != layout_.rank) continue;
    std::vector<GO> gids;
    for (mesh::NodeId n : coupling.nodes)
      for (int c = 0; c < 3; ++c) gids.push_back(layout_.dof(n, c));
    couplingGids.push_back(std::move(gids));
  }
  // Row capacity: 3 dofs per node coupled to the row's node through some element or contact. 27
  // nodes on a structured mesh, more where an unstructured mesh gathers more elements around a node.
  std::size_t maxNeighbours = 0;
  {
    std::vector<std::vector<mesh::NodeId>> neighbours(mesh.numNodes());
    for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
      const auto &hex = mesh.elements[layout_.localElements[i]];
      for (mesh::NodeId a : hex) neighbours[a].insert(neighbours[a].end(), hex.begin(), hex.end());
    }
    for (const model::NodeCoupling &coupling : couplings) {
      if (layout_.elementOwner[coupling.element] != layout_.rank) continue;
      for (mesh::NodeId a : coupling.nodes)
        neighbours[a].insert(neighbours[a].end(), coupling.nodes.begin(), coupling.nodes.end());
    }
    for (auto &n : neighbours) {
      std::sort(n.begin(), n.end());
      maxNeighbours = std::max(maxNeighbours, static_cast<std::size_t>(std::unique(n.begin(), n.end()) - n.begin()));
    }
  }
  graph_ = Teuchos::rcp(new FEGraph(ownedMap, overlapMap, 3 * maxNeighbours));
  graph_->beginAssembly();
  for (const auto &gids : elementGids_) {
    Teuchos::ArrayView<const GO> cols(gids.data(), 24);
    for (GO row : gids) graph_->insertGlobalIndices(row, cols);
  }
  for (const auto &gids : couplingGids) {
    Teuchos::ArrayView<const GO> cols(gids.data(), static_cast<Teuchos::Ordinal>(gids.size()));
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

void Assembler::assignFreeDofs(const Vector &solution, Vector &u) const {
  const auto from = solution.getData(0);
  auto to = u.getDataNonConst(0);
  for (std::size_t k = 0; k < layout_.ownedNodes.size(); ++k)
    for (int c = 0; c < 3; ++c)
      if (!constrained_[3 * layout_.ownedNodes[k] + c]) to[3 * k + c] = from[3 * k + c];
}

void Assembler::importToOverlap(const Vector &u, Vector &overlap) const {
  overlap.doImport(u, *importer_, Tpetra::INSERT);
}

void Assembler::importPrescribed(const Vector &u, double time, Vector &overlap) const {
  importToOverlap(u, overlap);
  auto data = overlap.getDataNonConst(0);
  for (const PrescribedDof &d : prescribedDofs_)
    data[d.lid] = scene_.dirichlet[d.condition].prescribed(d.component, scene_.mesh.nodes[d.node], time);
}

fem::NodeMatrix Assembler::elementDisplacement(std::size_t i, const Teuchos::ArrayRCP<const double> &uData) const {
  fem::NodeMatrix ue;
  for (int a = 0; a < 8; ++a)
    for (int c = 0; c < 3; ++c) ue(a, c) = uData[elementLids_[i][3 * a + c]];
  return ue;
}

PressureCoupling Assembler::pressureCoupling(const Vector &u) const {
  Vector uOverlap(layout_.overlapMap());
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  const std::size_t n = layout_.localElements.size();
  PressureCoupling out;
  out.pressureMap = layout_.elementMap();
  out.volumeGradient = Teuchos::rcp(new CrsMatrix(out.pressureMap, 24));
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
  out.volumeGradient->fillComplete(layout_.ownedMap(), out.pressureMap);
  return out;
}

std::vector<fem::MixedBase> Assembler::mixedBases(const Vector &u, const std::vector<double> &lambda,
                                                  const std::vector<fem::MixedBase> *previous) const {
  Vector uOverlap(layout_.overlapMap());
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  std::vector<fem::MixedBase> bases(layout_.localElements.size());
  for (std::size_t i = 0; i < bases.size(); ++i)
    bases[i] = fem::mixedBase(scene_.mesh.elementCoordinates(layout_.localElements[i]), elementDisplacement(i, uData),
                              previous ? &(*previous)[i] : nullptr,
                              volumetricLaw(static_cast<std::size_t>(layout_.localElements[i])), lambda[i]);
  return bases;
}

AssemblyStatus Assembler::assemble(const Vector &u, double time, const std::vector<double> &lambda,
                                   const std::vector<fem::MixedBase> *bases, Vector *f, FEMatrix *K,
                                   BasePoint point, const ElementForceCorrection *correction,
                                   const std::vector<char> *onlyElements) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  const bool trialPoint = point == BasePoint::trial || K == nullptr;
  Vector uOverlap(layout_.overlapMap()), fOverlap(layout_.overlapMap());
  importPrescribed(u, time, uOverlap);
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
      if (onlyElements && !(*onlyElements)[i]) continue;
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
      if (correction)
        correction->add(i, ue, lambda[i], volumetricLaw(static_cast<std::size_t>(e)), r, re, K ? &ke : nullptr);
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
  const Comm &comm = *layout_.comm();
  int globalValid = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, localValid, Teuchos::outArg(globalValid));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, localMinJ, Teuchos::outArg(status.minJ));
  double forceSquares = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, localForceSquares, Teuchos::outArg(forceSquares));
  status.forceScale = std::sqrt(forceSquares);
  status.valid = globalValid == 1;
  return status;
}

void Assembler::forEachElement(const Vector &u, const std::vector<double> &lambda,
                               const std::function<bool(std::size_t)> &which, const ElementVisit &visit) const {
  Vector uOverlap(layout_.overlapMap());
  importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    if (!which(i)) continue;
    const fem::NodeMatrix X = scene_.mesh.elementCoordinates(layout_.localElements[i]);
    const fem::NodeMatrix ue = elementDisplacement(i, uData);
    visit(i, ue, evaluateElement(i, X, ue, lambda[i], nullptr, false, fem::Q1P0Output::ResidualOnly),
          volumetricLaw(static_cast<std::size_t>(layout_.localElements[i])));
  }
}

void Assembler::assembleMass(FEMatrix &M, fem::MassLumping lumping, ConstrainedDofs constrained) const {
  const mesh::HexMesh &mesh = scene_.mesh;
  M.beginAssembly();
  M.setAllToScalar(0.0);
  auto local = M.getLocalMatrixHost();
  const ElementScatter &scatter = elementScatter(M, local);
  int localValid = 1;
  for (std::size_t i = 0; i < layout_.localElements.size(); ++i) {
    const auto e = layout_.localElements[i];
    fem::ElementMass me;
    if (!fem::hexMass(mesh.elementCoordinates(e), scene_.tissueOf(static_cast<std::size_t>(e)).density, lumping, me))
      localValid = 0;
    if (constrained == ConstrainedDofs::zeroed)
      for (int l = 0; l < 24; ++l)
        if (constrained_[3 * mesh.elements[e][l / 3] + l % 3]) {
          me.row(l).setZero();
          me.col(l).setZero();
        }
    scatter.add(i, me, local.values.data());
  }
  M.endAssembly();
  int globalValid = 0;
  Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_MIN, localValid, Teuchos::outArg(globalValid));
  // The constructor refused non-positive Jacobians already, so this is a broken invariant.
  if (globalValid != 1) throw std::logic_error("Assembler::assembleMass: a degenerate element");
}

Vector Assembler::loadResidual(const Vector &u, double time, const LoadContribution *only) const {
  Vector uOverlap(layout_.overlapMap()), fOverlap(layout_.overlapMap()), f(layout_.ownedMap());
  importPrescribed(u, time, uOverlap);
  auto uData = uOverlap.getData(0);
  {
    auto fData = fOverlap.getDataNonConst(0);
    if (only) only->addTo(loadTarget(uData, &fData, nullptr, /*constrainedToo=*/false), time);
    else addLoads(uData, time, fData, nullptr, /*constrainedToo=*/false, everyLoad);
  }
  f.doExport(fOverlap, *exporter_, Tpetra::ADD);
  return f;
}

LoadTarget Assembler::loadTarget(const Teuchos::ArrayRCP<const double> &uData, Teuchos::ArrayRCP<double> *fData,
                                 FEMatrix *K, bool constrainedToo) const {
  return {scene_, layout_, *layout_.overlapMap(), constrained_, uData, fData, K, constrainedToo};
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

const materials::VolumetricEnergy &Assembler::volumetricLaw(std::size_t element) const {
  if (!tangentLaws_) return scene_.tissueOf(element).volumetric;
  return (*tangentLaws_)[scene_.elementTissue.empty() ? 0 : static_cast<std::size_t>(scene_.elementTissue[element])];
}

fem::Q1P0Result Assembler::evaluateElement(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue,
                                           double lambda, const fem::MixedBase *base, bool extrapolate,
                                           fem::Q1P0Output what) const {
  const auto e = static_cast<std::size_t>(layout_.localElements[i]);
  const materials::VolumetricEnergy &volumetric = volumetricLaw(e);
  if (scene_.formulation == model::ElementFormulation::PlainQ1) {
    if (!isMuscleElement(e))
      return fem::evaluatePlainQ1(X, ue, fem::UniformPointLaw(*scene_.tissueOf(e).matrix), volumetric, what);
    return fem::evaluatePlainQ1(X, ue, musclePointLaw(i, nullptr), volumetric, what);
  }
  const fem::Q1P0DisplacementPart &part = displacementPart(i, X, ue, what).part;
  if (base) return fem::finishQ1P0Mixed(part, ue, *base, volumetric, lambda, extrapolate, what);
  return fem::finishQ1P0(part, volumetric, lambda, what);
}

ElementPartKey Assembler::partKey(std::size_t i, const fem::NodeMatrix &ue) const {
  ElementPartKey key;
  key.u = ue;
  key.alpha = history_.familyActivation(i);
  key.dt = history_.dt();
  key.revision = history_.revision();
  return key;
}

const ElementPart &Assembler::displacementPart(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue,
                                               fem::Q1P0Output what) const {
  const bool keep = parts_.keeps(i);
  const ElementPartKey key = keep ? partKey(i, ue) : ElementPartKey{};
  if (keep)
    if (const ElementPart *kept = parts_.find(i, key, what)) {
      parts_.count(true);
      return *kept;
    }
  parts_.count(false);
  ElementPart &slot = keep ? parts_.slot(i, key) : scratchPart_;
  const auto e = static_cast<std::size_t>(layout_.localElements[i]);
  if (!isMuscleElement(e)) {
    fem::evaluateDisplacementPart(X, ue, fem::UniformPointLaw(*scene_.tissueOf(e).matrix), what, slot.part);
    return slot;
  }
  fem::evaluateDisplacementPart(X, ue, musclePointLaw(i, &slot.muscle), what, slot.part);
  if (keep) parts_.kept(i);
  return slot;
}

bool Assembler::isMuscleElement(std::size_t e) const {
  return scene_.muscles.hasFibres() && scene_.muscles.elementRegion[e] >= 0;
}

model::TissuePointLaw Assembler::musclePointLaw(std::size_t i, model::ElementMuscleResponse *record) const {
  const auto e = static_cast<std::size_t>(layout_.localElements[i]);
  std::array<const double *, 8> lambdaCOld;
  std::array<double *, 8> lambdaCStart;
  for (int q = 0; q < 8; ++q) {
    lambdaCOld[q] = history_.committedLambdaC(i, q);
    lambdaCStart[q] = history_.lambdaCStart(i, q);
  }
  const auto region = static_cast<std::size_t>(scene_.muscles.elementRegion[e]);
  return model::TissuePointLaw(*scene_.muscles.regions[region].law, scene_.muscles.directions[e],
                               history_.familyActivation(i), history_.dt(), lambdaCOld, record,
                               scene_.muscles.pointDirectionsOf(e), lambdaCStart);
}

const model::ElementMuscleResponse *Assembler::keptMuscleResponse(std::size_t i, const fem::NodeMatrix &ue) const {
  if (!parts_.keeps(i)) return nullptr;
  const ElementPart *kept = parts_.find(i, partKey(i, ue), fem::Q1P0Output::ResidualOnly);
  if (!kept || !kept->part.valid || kept->part.lawFailed) return nullptr;
  parts_.count(true);
  return &kept->muscle;
}

double Assembler::externalForceNorm(double time) const {
  Vector fOverlap(layout_.overlapMap()), f(layout_.ownedMap());
  {
    auto fData = fOverlap.getDataNonConst(0);
    addLoads(Teuchos::ArrayRCP<const double>(), time, fData, nullptr, /*constrainedToo=*/false,
             [](const LoadContribution &l) { return l.kind() == LoadContribution::Kind::dead; });
  }
  f.doExport(fOverlap, *exporter_, Tpetra::ADD);
  return f.norm2();
}

} // namespace glossa::assembly
