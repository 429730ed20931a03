#pragma once
// Global assembly of the condensed Q1-P0 system on Tpetra: the only place where element
// kernels meet distributed objects. It gathers element displacements from the overlap vector,
// calls the Eigen kernels (fem/, loads/) and sums element vectors and matrices into the owned
// residual and the FECrsMatrix whose graph is built once.
//
// Dirichlet dofs stay in the system (so MueLu sees 3 dofs on every node) with the rows and
// columns of the element matrices zeroed and a diagonal `dirichletScale`; their residual is
// zero because the solution vector holds the prescribed values before every solve.

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Teuchos_RCP.hpp>

#include "assembly/ElementScatter.hpp"
#include "assembly/LoadContribution.hpp"
#include "assembly/DofLayout.hpp"
#include "assembly/TpetraTypes.hpp"
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

// Element-constant results for output and for the Uzawa update.
struct ElementFields {
  std::vector<double> theta, pressure, minJ; // per local element
  std::vector<Eigen::Matrix<double, 3, 3>> cauchy;
  std::vector<double> referenceVolume;
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

// A Dirichlet condition's reaction: the force the support exerts on the body [N], and its power [W].
struct Reaction {
  Eigen::Vector3d force;
  double power;
};

// Which rank owns which element, node and dof: the deck's partitioner (Zoltan2) or the built-in
// bisection. Collective.
DofLayout distributeScene(const model::Scene &scene, const Teuchos::RCP<const Comm> &comm);

class Assembler {
public:
  // `history`, the muscle state of the layout's local elements (owned by the caller, who begins
  // steps and commits them), is read by every assembly: the trial activation, the step and the
  // committed lambda_c.
  Assembler(const model::Scene &scene, DofLayout layout, const model::MuscleHistory &history,
            Teuchos::RCP<const Comm> comm);

  const model::Scene &scene() const { return scene_; }
  const DofLayout &layout() const { return layout_; }
  Teuchos::RCP<const Map> ownedMap() const { return ownedMap_; }
  // One entry per local element (GID = mesh element id): multipliers and element pressures.
  Teuchos::RCP<const Map> elementMap() const { return pressureMap_; }
  Teuchos::RCP<const Comm> comm() const { return comm_; }
  std::size_t numLocalElements() const { return layout_.localElements.size(); }

  // A matrix on the once-built graph.
  Teuchos::RCP<FEMatrix> createMatrix() const;

  // Writes the prescribed displacements at time t into u (owned part).
  void applyDirichlet(Vector &u, double time) const;
  // Zeroes the owned entries of v at the dofs a (non-elastic) Dirichlet condition fixes.
  void zeroConstrainedDofs(Vector &v) const;

  // Residual f = f_int(u; Lambda) - f_ext(t) and, if K is given, the tangent. `lambda` is the
  // augmented Lagrange multiplier per local element. With `bases` (one per local element, Q1-P0
  // only) the pressure and dilatation are the three-field Newton iterates of fem::MixedBase:
  // with K, the bases' own state (u is their iterate); without, the Newton update from them to
  // the trial u. Without `bases` they are condensed exactly from u. Collective.
  AssemblyStatus assemble(const Vector &u, double time, const std::vector<double> &lambda,
                          const std::vector<fem::MixedBase> *bases, Vector *f, FEMatrix *K) const {
    return assemble(u, time, lambda, bases, f, K, /*trialPoint=*/K == nullptr);
  }
  // The same with the choice explicit: trialPoint, the Newton update from the bases to u (also
  // for the tangent: the residual and tangent of a trial point in one pass, which equal those
  // of the next iterate's own state once the trial point is accepted).
  AssemblyStatus assemble(const Vector &u, double time, const std::vector<double> &lambda,
                          const std::vector<fem::MixedBase> *bases, Vector *f, FEMatrix *K, bool trialPoint) const;

  // The element work of assemble(u, ..., f, K) alone: every local element's kernel with its
  // point law, residual and tangent, nothing gathered into f or K (bench/assembly_cost compares
  // the two). Returns the number of elements evaluated. Collective (imports u).
  std::size_t evaluateElementsOnly(const Vector &u, const std::vector<double> &lambda) const;

  // The three-field linearisation at u for every local element (see fem::MixedBase);
  // `previous` carries the dilatation iterates forward. Collective (imports u).
  std::vector<fem::MixedBase> mixedBases(const Vector &u, const std::vector<double> &lambda,
                                         const std::vector<fem::MixedBase> *previous) const;

  // The mixed system's coupling block and element volumes at u (see PressureCoupling); an
  // inverted element gets a zero row (the tangent's assembly reports it). Collective (imports u).
  PressureCoupling pressureCoupling(const Vector &u) const;

  // Element dilatation, pressure, stress, min J (local elements). Collective (imports u).
  ElementFields elementFields(const Vector &u, const std::vector<double> &lambda) const;
  // The residual of the loads alone (assemble without the element terms): f at (u, t) minus
  // f_int(u), for df/dt at fixed u. Collective.
  Vector loadResidual(const Vector &u, double time) const;

  // Only theta, pressure and referenceVolume of elementFields, from the kinematics and the
  // volumetric law without the point laws (the same numbers on the Q1-P0 element; plain Q1 takes
  // the full pass): what the Uzawa loop needs after every solve.
  ElementFields elementDilatations(const Vector &u, const std::vector<double> &lambda) const;

  // The element of the whole mesh with the smallest corner det F at u (fem::minCornerJacobian),
  // for the check after each converged step that Gauss-point J cannot make. Collective.
  struct WorstCorner {
    double J;
    mesh::ElementId element; // lowest id among equals
    // The same over regular corners (fem::minRegularCornerJacobian with kRegularCorner).
    double regularJ = 0.0;
    mesh::ElementId regularElement = 0;
  };
  static constexpr double kRegularCorner = 0.2;
  WorstCorner worstCorner(const Vector &u) const;

  const model::MuscleHistory &muscleHistory() const { return history_; }
  // The external muscles among the loads (null without them).
  const ExternalMuscleForces *externalMuscles() const { return externalMuscles_; }

  // The reaction of every Dirichlet condition (scene order): the sum over its nodes of the
  // internal minus external force in its fixed components, i.e. the force the support exerts.
  // A node in several conditions counts in each. For an elastic support: the sum of its springs'
  // forces on the body, -k (u - g), over the components no other condition fixes. With it its
  // power, sum over the nodes and fixed components of R . du_prescribed/dt: with a displacement
  // driven cavity wall, the pressure it holds is that power over the cavity's volume rate. Collective.
  std::vector<Reaction> reactions(const Vector &u, double time, const std::vector<double> &lambda) const;
  // Per face set named: the force the world exerts on the body through it, sum over the set's
  // nodes of f_int - f_body (internal forces less body forces): a support's reaction, a load's
  // resultant. A node shared by two sets counts in both.
  std::vector<Eigen::Vector3d> faceSetResultants(const Vector &u, double time, const std::vector<double> &lambda,
                                                 const std::vector<std::string> &faceSets) const;
  // Per face set named: 1/3 of the integral of x . n over its deformed faces (2x2 Gauss points,
  // exact for bilinear faces), n the body's outward normal: the volume of the body for its whole
  // boundary, minus that of a cavity for the cavity's wall. Collective.
  std::vector<double> enclosedVolumes(const Vector &u, const std::vector<std::string> &faceSets) const;

  // Norm of the external force vector at time t (the scale of the Newton tolerance).
  double externalForceNorm(double time) const;

  // Nodal coordinates (owned nodes, 3 columns) and the 6 rigid-body modes (owned dofs) that
  // MueLu needs for elasticity.
  Teuchos::RCP<MultiVector> coordinates() const;
  Teuchos::RCP<MultiVector> rigidBodyModes() const;

  // All nodal displacements by mesh node id (3 per node) on every rank. Collective.
  std::vector<double> gatherDisplacement(const Vector &u) const;
  // The inverse of gatherDisplacement: the owned part of u from all nodal displacements.
  void scatterDisplacement(const std::vector<double> &all, Vector &u) const;
  // The local elements' entries of a per-mesh-element field (one component).
  std::vector<double> localElementValues(const std::vector<double> &all) const;
  // A per-local-element field gathered by mesh element id on every rank. Collective.
  std::vector<double> gatherElementField(const std::vector<double> &local, int components) const;

  // u with the ghosts of the local elements (the overlap map). Collective.
  void importToOverlap(const Vector &u, Vector &overlap) const;
  Teuchos::RCP<const Map> overlapMap() const { return overlapMap_; }
  // Local element i's nodal displacements from the overlap vector's data.
  fem::NodeMatrix elementDisplacement(std::size_t localElement, const Teuchos::ArrayRCP<const double> &uOverlap) const;
  // A load target at the overlap displacement, for evaluations outside assemble (MuscleResponse).
  LoadTarget loadTarget(const Teuchos::ArrayRCP<const double> &uOverlap, Teuchos::ArrayRCP<double> *fData, FEMatrix *K,
                        bool constrainedToo) const;

private:
  // Owned f_int - f_body, less the surface loads (tractions, follower loads) too when asked, at
  // every dof, constrained ones included: reactions and face-set resultants sum it over nodes.
  Vector nodalForces(const Teuchos::ArrayRCP<const double> &uData, double time, const std::vector<double> &lambda,
                     bool surfaceLoads) const;
  // The element kernel with the point law of local element i (its muscle law if it has fibres).
  fem::Q1P0Result evaluateElement(std::size_t i, const fem::NodeMatrix &X, const fem::NodeMatrix &ue, double lambda,
                                  const fem::MixedBase *base, bool extrapolate, fem::Q1P0Output what) const;
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
  Teuchos::RCP<const Comm> comm_;
  DofLayout layout_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_, pressureMap_;
  Teuchos::RCP<Import> importer_;
  Teuchos::RCP<Export> exporter_;
  Teuchos::RCP<FEGraph> graph_;
  std::vector<char> constrained_;                       // per mesh dof 3*node+c
  std::vector<std::array<LO, 24>> elementLids_;         // overlap local ids per local element
  std::vector<std::array<GO, 24>> elementGids_;
  std::vector<int> nodeMultiplicity_;                    // elements sharing each mesh node
  double dirichletScale_ = 1.0;
  mutable std::shared_ptr<const ElementScatter> scatter_;
  mutable const void *scatterPattern_ = nullptr;
  const model::MuscleHistory &history_;
  std::vector<std::unique_ptr<LoadContribution>> loads_; // the scene's loads (LoadContribution.hpp)
  const ExternalMuscleForces *externalMuscles_ = nullptr; // among them, for the muscle history
};

} // namespace glossa::assembly
