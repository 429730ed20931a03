#pragma once
// Global assembly of the condensed Q1-P0 system on Tpetra: the only place where element
// kernels meet distributed objects. It gathers element displacements from the overlap vector,
// calls the Eigen kernels (fem/, loads/) and sums element vectors and matrices into the owned
// residual and the FECrsMatrix whose graph is built once.
//
// Dirichlet dofs stay in the system (so MueLu sees 3 dofs on every node) with the rows and
// columns of the element matrices zeroed and a diagonal `dirichletScale`; their residual is
// zero because the solution vector holds the prescribed values before every solve.
//
// It answers what Newton, the Uzawa loop and the linear solvers ask of the problem: the residual,
// its tangent, the mixed method's pressure blocks, the loads alone and their scale. What a state
// is reported as (fields, reactions, resultants, volumes, the corner check, whole-mesh gathers)
// is the ResultEvaluator's, from the same element and load passes (MFEM's split between the form
// that assembles and what is computed from a solution); the coordinates and rigid-body modes the
// multilevel preconditioners need are in NullSpace.hpp.

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Teuchos_RCP.hpp>

#include "assembly/DistributedLayout.hpp"
#include "assembly/ElementForceCorrection.hpp"
#include "assembly/ElementPartCache.hpp"
#include "assembly/ElementScatter.hpp"
#include "assembly/LoadContribution.hpp"
#include "assembly/TpetraTypes.hpp"
#include "fem/HexMass.hpp"
#include "fem/Q1P0Element.hpp"
#include "model/MuscleHistory.hpp"
#include "model/Scene.hpp"

namespace glossa::assembly {

struct AssemblyStatus {
  bool valid = true;   // false: J <= 0 in some element (on any rank)
  double minJ = 1.0;   // global minimum over quadrature points
  // sqrt(sum over elements of forceScale^2) (fem::Q1P0Result): the size of the terms that
  // cancel in the assembled residual, whose round-off sets the residual's floor.
  double forceScale = 0.0;
};

// The pressure blocks of the uncondensed (mixed) Q1-P0 system at a displacement
// (Incompressibility/method = mixed): one pressure unknown per element, its coupling row
// B_e = dv_e/du (the current volume's gradient, fem::elementVolumeGradient) with the columns of
// constrained dofs zero, and the element volumes from which the solver forms the constraint
// residual v_e - V_e theta_phys(p_e) and the pressure blocks.
struct PressureCoupling {
  Teuchos::RCP<const Map> pressureMap;      // one entry per local element, GID = mesh element id
  Teuchos::RCP<CrsMatrix> volumeGradient;   // B: range = pressureMap, domain = the owned dof map
  std::vector<double> referenceVolume, currentVolume; // per local element
};

class Assembler {
public:
  // `history`, the muscle state of the layout's local elements (owned by the caller, who begins
  // steps and commits them), is read by every assembly: the trial activation, the step and the
  // committed lambda_c.
  // `tangentLaws`: each tissue's volumetric law in the tangent (kappa_t; the augmentation's,
  // solvers/incompressibility/Augmentation, which may raise it during a run and which must
  // outlive the assembler); null: the scene's own laws. The scene itself is never changed.
  // `parts`: whether element passes keep each muscle element's displacement part (ElementPartCache).
  Assembler(const model::Scene &scene, DofLayout layout, const model::MuscleHistory &history,
            Teuchos::RCP<const Comm> comm, const std::vector<materials::VolumetricEnergy> *tangentLaws = nullptr,
            ElementParts parts = ElementParts::Kept);

  const model::Scene &scene() const { return scene_; }
  // Who owns what, with the communicator, the maps and the number of local elements.
  const DistributedLayout &layout() const { return layout_; }

  // A matrix on the once-built graph.
  Teuchos::RCP<FEMatrix> createMatrix() const;

  // Writes the prescribed displacements at time t into u (owned part).
  void applyDirichlet(Vector &u, double time) const;
  // Zeroes the owned entries of v at the dofs a (non-elastic) Dirichlet condition fixes.
  void zeroConstrainedDofs(Vector &v) const;
  // Copies `solution` into `u` except at those dofs, where `u` keeps what it holds (the prescribed
  // values, applyDirichlet). Their Newton updates solve diagonal rows with a zero right-hand side,
  // which an iterative solve meets only to its tolerance: copied, they would drift by ~1e-11 m.
  void assignFreeDofs(const Vector &solution, Vector &u) const;

  // With `bases` (assemble): where the three-field pressure and dilatation are taken.
  enum class BasePoint {
    // With K, the bases' own state (u is their iterate); without, the Newton update from them to
    // the trial u.
    byRequest,
    // The Newton update from the bases to u, for the tangent too: the residual and tangent of a
    // trial point in one pass, which equal those of the next iterate's own state once the trial
    // point is accepted.
    trial
  };
  // Residual f = f_int(u; Lambda) - f_ext(t) and, if K is given, the tangent. `lambda` is the
  // augmented Lagrange multiplier per local element. With `bases` (one per local element, Q1-P0
  // only) the pressure and dilatation are the three-field Newton iterates of fem::MixedBase, at
  // `point`. Without `bases` they are condensed exactly from u. A `correction` adds to each
  // element's force and tangent after its kernel (a dynamic run's energy-conserving step).
  // `onlyElements`: the local elements to evaluate (null: all), for differences in a parameter
  // that only some elements see, the loads still whole. Collective.
  AssemblyStatus assemble(const Vector &u, double time, const std::vector<double> &lambda,
                          const std::vector<fem::MixedBase> *bases, Vector *f, FEMatrix *K,
                          BasePoint point = BasePoint::byRequest,
                          const ElementForceCorrection *correction = nullptr,
                          const std::vector<char> *onlyElements = nullptr) const;

  // Each local element that `which` admits, evaluated at the owned displacement u (with its
  // ghosts; u holds its prescribed values) and condensed exactly, handed to `visit` with its
  // displacement, kernel result and the volumetric law the kernel used. Collective (imports u).
  using ElementVisit = std::function<void(std::size_t, const fem::NodeMatrix &, const fem::Q1P0Result &,
                                          const materials::VolumetricEnergy &)>;
  void forEachElement(const Vector &u, const std::vector<double> &lambda, const std::function<bool(std::size_t)> &which,
                      const ElementVisit &visit) const;

  // The mass matrix into M (a createMatrix matrix): fem::hexMass of every element at its
  // tissue's density, the reference configuration's mass, constant in a Lagrangian run.
  // `keep`: every entry, for the products M a that carry a prescribed motion's inertia to the
  // free dofs; `zeroed`: the rows and columns of constrained dofs empty, for the tangent (whose
  // own diagonal holds those rows). Collective.
  enum class ConstrainedDofs { keep, zeroed };
  void assembleMass(FEMatrix &M, fem::MassLumping lumping, ConstrainedDofs constrained) const;

  // The three-field linearisation at u for every local element (see fem::MixedBase);
  // `previous` carries the dilatation iterates forward. Collective (imports u).
  std::vector<fem::MixedBase> mixedBases(const Vector &u, const std::vector<double> &lambda,
                                         const std::vector<fem::MixedBase> *previous) const;

  // The mixed system's coupling block and element volumes at u (see PressureCoupling); an
  // inverted element gets a zero row (the tangent's assembly reports it). Collective (imports u).
  PressureCoupling pressureCoupling(const Vector &u) const;

  // The residual of the loads alone (assemble without the element terms): f at (u, t) minus
  // f_int(u), for df/dt at fixed u. Collective.
  // `only`: that load alone (a contribution over this assembler's scene), not the scene's.
  Vector loadResidual(const Vector &u, double time, const LoadContribution *only = nullptr) const;

  // Norm of the external force vector at time t (the scale of the Newton tolerance).
  double externalForceNorm(double time) const;

  // Element evaluations finished from a kept displacement part, and evaluated (ElementPartCache).
  ElementPartCounts elementPartCounts() const { return parts_.counts(); }

private:
  // The ResultEvaluator reports a state from this class's own element and load passes (a
  // reaction is the residual's nodal sum at a support, an element field the same kernel call),
  // so its numbers are the residual's and cannot drift from a copy. Friendship gives it those
  // private passes without making them public, or moving the data to a structure both would
  // share; it holds the Assembler const, so it only reads.
  friend class ResultEvaluator;

  // u with the ghosts of the local elements (the overlap map). Collective.
  void importToOverlap(const Vector &u, Vector &overlap) const;
  // The same with the prescribed values at time t at every constrained dof, whatever u holds there:
  // the residual and tangent depend on the free dofs alone. An iterative solve meets the constrained
  // rows of a Newton update (diagonal, zero right-hand side) only to its tolerance, and on several
  // ranks the preconditioner's error there is ~1e-9 m; assembled at such an iterate, the free dofs
  // converged to the equilibrium of the drifted supports. Collective.
  void importPrescribed(const Vector &u, double time, Vector &overlap) const;
  // Local element i's nodal displacements from the overlap vector's data.
  fem::NodeMatrix elementDisplacement(std::size_t localElement, const Teuchos::ArrayRCP<const double> &uOverlap) const;
  // A load target at the overlap displacement.
  LoadTarget loadTarget(const Teuchos::ArrayRCP<const double> &uOverlap, Teuchos::ArrayRCP<double> *fData, FEMatrix *K,
                        bool constrainedToo) const;
  // The element kernel with the point law of local element i (its muscle law if it has fibres),
  // finished from its displacement part.
  fem::Q1P0Result evaluateElement(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue, double lambda,
                                  const fem::MixedBase *base, bool extrapolate, fem::Q1P0Output what) const;
  // Local element i's displacement part at ue: kept from an earlier pass at the same key, or
  // evaluated now (and kept, for a muscle element: ElementPartCache).
  const ElementPart &displacementPart(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue,
                                      fem::Q1P0Output what) const;
  ElementPartKey partKey(std::size_t i, const fem::NodeMatrix &ue) const;
  // Whether mesh element e has fibres; the point law of muscle element i (local), writing what
  // its points compute to `record` when given.
  bool isMuscleElement(std::size_t e) const;
  model::TissuePointLaw musclePointLaw(std::size_t i, model::ElementMuscleResponse *record) const;
  // What the point laws of muscle element i computed at ue in the kept part, if it is kept at the
  // history's present key and every point law succeeded; null otherwise.
  const model::ElementMuscleResponse *keptMuscleResponse(std::size_t i, const fem::NodeMatrix &ue) const;
  // The loads that `which` admits (assembly order: dead tractions, body forces, follower
  // pressures, external muscles, elastic supports) subtracted at (u, t) from the overlap residual
  // (at constrained dofs only if `constrainedToo`) and, with K, their tangent. False if one could
  // not be evaluated on this rank.
  bool addLoads(const Teuchos::ArrayRCP<const double> &uOverlap, double time, Teuchos::ArrayRCP<double> &fData,
                FEMatrix *K, bool constrainedToo, const std::function<bool(const LoadContribution &)> &which) const;
  static bool everyLoad(const LoadContribution &) { return true; }
  // The offsets of every element entry in K's values while K is open for assembly (its
  // owned-plus-shared pattern), found on first use for that pattern.
  const ElementScatter &elementScatter(const FEMatrix &K, const FEMatrix::local_matrix_host_type &local) const;

  const model::Scene &scene_;
  DistributedLayout layout_;
  Teuchos::RCP<Import> importer_;
  Teuchos::RCP<Export> exporter_;
  Teuchos::RCP<FEGraph> graph_;
  std::vector<char> constrained_;                       // per mesh dof 3*node+c
  struct PrescribedDof {
    LO lid;                // in the overlap map
    std::size_t condition; // in scene_.dirichlet
    mesh::NodeId node;
    int component;
  };
  std::vector<PrescribedDof> prescribedDofs_; // the constrained dofs of the overlap map
  std::vector<std::array<LO, 24>> elementLids_;         // overlap local ids per local element
  std::vector<std::array<GO, 24>> elementGids_;
  std::vector<int> nodeMultiplicity_;                    // elements sharing each mesh node
  double dirichletScale_ = 1.0;
  mutable std::shared_ptr<const ElementScatter> scatter_;
  mutable const void *scatterPattern_ = nullptr;
  const model::MuscleHistory &history_;
  mutable ElementPartCache parts_;
  mutable ElementPart scratchPart_; // the part of an element that keeps none
  const std::vector<materials::VolumetricEnergy> *tangentLaws_; // per tissue; null: the scene's
  // The volumetric law the tangent carries in mesh element e.
  const materials::VolumetricEnergy &volumetricLaw(std::size_t element) const;
  std::vector<std::unique_ptr<LoadContribution>> loads_; // the scene's loads (LoadContribution.hpp)
  const ExternalMuscleForces *externalMuscles_ = nullptr; // among them, for the muscle history
};

} // namespace glossa::assembly
