#pragma once
// What a state of the distributed problem is reported as, beside the Assembler that builds its
// residual and tangent (MFEM's split between the form that assembles and what is computed from a
// solution): element fields and dilatations, the worst element corner, the reactions of the
// Dirichlet conditions, face-set resultants and enclosed volumes, the gathers and scatters between
// distributed vectors and whole-mesh arrays that output, checkpoints and controllers use, and the
// overlap access with which the muscle state is updated at a converged step (MuscleResponse).
//
// A view: it holds the Assembler by reference and keeps no state of its own, so whoever has an
// Assembler may build one, at no cost, valid while that Assembler lives; components keep their
// own copy. It evaluates with the Assembler's own element kernels and load passes (it is the
// Assembler's friend: a reaction is the residual's nodal sum at a support, an element field the
// same kernel call), so its numbers are those of the residual.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "assembly/Assembler.hpp"

namespace glossa::assembly {

// Element-constant results for output and for the Uzawa update.
struct ElementFields {
  std::vector<double> theta, pressure, minJ; // per local element
  std::vector<Eigen::Matrix<double, 3, 3>> cauchy;
  std::vector<double> referenceVolume;
};

// A Dirichlet condition's reaction: the force the support exerts on the body [N], and its power [W].
struct Reaction {
  Eigen::Vector3d force;
  double power;
};

class ResultEvaluator {
public:
  explicit ResultEvaluator(const Assembler &assembler)
      : assembler_(assembler), scene_(assembler.scene()), layout_(assembler.layout()) {}

  const Assembler &assembler() const { return assembler_; }
  const model::Scene &scene() const { return scene_; }
  // The muscle state the assembler reads (trial activation, committed lambda_c).
  const model::MuscleHistory &muscleHistory() const { return assembler_.history_; }
  // The external muscles among the loads (null without them).
  const ExternalMuscleForces *externalMuscles() const { return assembler_.externalMuscles_; }

  // Element dilatation, pressure, stress, min J (local elements). Collective (imports u).
  ElementFields elementFields(const Vector &u, const std::vector<double> &lambda) const;
  // Only theta, pressure and referenceVolume of elementFields, from the kinematics and the
  // volumetric law without the point laws (the same numbers on the Q1-P0 element; plain Q1 takes
  // the full pass): what the Uzawa loop needs after every solve.
  ElementFields elementDilatations(const Vector &u, const std::vector<double> &lambda) const;

  // The stored energy of the whole mesh at u [J]: every element's int psi_iso dV + V U(theta_p),
  // U the tissue's physical volumetric law at the dilatation it gives the element pressure (not
  // the augmented Lagrangian's U_t(theta) + Lambda (theta - 1) the kernel carries; none where
  // kappa is infinite); a muscle's active stress stores none, so with activation it is the
  // passive part. Collective.
  double storedEnergy(const Vector &u, const std::vector<double> &lambda) const;

  // The element of the whole mesh with the smallest corner det F at u (fem::minCornerJacobian),
  // for the check after each converged step that Gauss-point J cannot make. Collective.
  struct WorstCorner {
    double J;
    mesh::ElementId element; // lowest id among equals
    // The same over regular corners (fem::minRegularCornerJacobian with kRegularCorner).
    double regularJ = 0.0;
    mesh::ElementId regularElement = 0;
    // The largest fraction of an element turned over since the reference (fem::turnedOverFraction),
    // the fold check, and that element's smallest corner det F.
    double turnedOver = 0.0;
    mesh::ElementId turnedOverElement = 0;
    double turnedOverCornerJ = 1.0;
  };
  static constexpr double kRegularCorner = 0.2;
  WorstCorner worstCorner(const Vector &u) const;

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

  // All nodal displacements by mesh node id (3 per node) on every rank. Collective.
  std::vector<double> gatherDisplacement(const Vector &u) const;
  // The inverse of gatherDisplacement: the owned part of u from all nodal displacements.
  void scatterDisplacement(const std::vector<double> &all, Vector &u) const;
  // The local elements' entries of a per-mesh-element field (one component).
  std::vector<double> localElementValues(const std::vector<double> &all) const;
  // A per-local-element field gathered by mesh element id on every rank. Collective.
  std::vector<double> gatherElementField(const std::vector<double> &local, int components) const;

  // u with the ghosts of the local elements (the overlap map). Collective.
  void importToOverlap(const Vector &u, Vector &overlap) const { assembler_.importToOverlap(u, overlap); }
  Teuchos::RCP<const Map> overlapMap() const { return layout_.overlapMap(); }
  // Local element i's nodal displacements from the overlap vector's data.
  fem::NodeMatrix elementDisplacement(std::size_t localElement, const Teuchos::ArrayRCP<const double> &uOverlap) const {
    return assembler_.elementDisplacement(localElement, uOverlap);
  }
  // What the point laws of muscle element i computed at ue, when the assembler keeps it from an
  // earlier pass at the same state (assembly/ElementPartCache); null otherwise.
  const model::ElementMuscleResponse *keptMuscleResponse(std::size_t localElement, const fem::NodeMatrix &ue) const {
    return assembler_.keptMuscleResponse(localElement, ue);
  }
  // A load target at the overlap displacement, for evaluations outside assemble (MuscleResponse).
  LoadTarget loadTarget(const Teuchos::ArrayRCP<const double> &uOverlap, Teuchos::ArrayRCP<double> *fData, FEMatrix *K,
                        bool constrainedToo) const {
    return assembler_.loadTarget(uOverlap, fData, K, constrainedToo);
  }

  // The element work of Assembler::assemble(u, ..., f, K) alone: every local element's kernel
  // with its point law, residual and tangent, nothing gathered into f or K (bench/assembly_cost
  // compares the two). Returns the number of elements evaluated. Collective (imports u).
  std::size_t evaluateElementsOnly(const Vector &u, const std::vector<double> &lambda) const;

private:
  // Owned f_int - f_body, less the surface loads (tractions, follower loads) too when asked, at
  // every dof, constrained ones included: reactions and face-set resultants sum it over nodes.
  Vector nodalForces(const Teuchos::ArrayRCP<const double> &uData, double time, const std::vector<double> &lambda,
                     bool surfaceLoads) const;

  const Assembler &assembler_;
  const model::Scene &scene_;
  const DistributedLayout &layout_;
};

} // namespace glossa::assembly
