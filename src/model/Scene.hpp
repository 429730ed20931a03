#pragma once
// The scene: what is simulated, independent of how it is solved (doc/developing.md). The mesh, the
// material with its fibres and muscle groups, boundary conditions and loads with their time
// functions, and the named points whose displacement is traced. No Trilinos.

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactState.hpp"
#include "contact/DeformablePair.hpp"
#include "contact/FaceContact.hpp"
#include "contact/MovingObstacle.hpp"
#include "contact/Obstacle.hpp"
#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "mesh/HexMesh.hpp"
#include "loads/PressureField.hpp"
#include "model/MuscleArchitecture.hpp"
#include "model/Tissue.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::model {

enum class ElementFormulation { Q1P0, PlainQ1 };

// u_i(node, t) = value_i * scale(t) for every fixed component i of every node in the set; or,
// for an elastic support (nodeStiffness > 0), a linear spring per node and listed component
// pulling u_i towards that value: the force on the body is -k (u_i - value_i scale(t)) (a
// component that another condition fixes stays fixed, and its spring carries nothing).
struct DirichletCondition {
  std::string name;
  std::vector<mesh::NodeId> nodes;
  std::array<bool, 3> fixed{false, false, false}; // the components the condition acts on
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  TimeFunction scale = TimeFunction::constant();
  double nodeStiffness = 0.0; // [N/m] per node and component; 0: fixed
  bool elastic() const { return nodeStiffness > 0.0; }
  // Per component, a prescribed displacement as an expression of the reference position and time
  // (Boundary conditions/<name>/ux, uy, uz); where empty, value * scale(t).
  std::array<std::function<double(const Eigen::Vector3d &, double)>, 3> expression;
  // The prescribed displacement of component c at a node of reference position X at time t.
  double prescribed(int c, const Eigen::Vector3d &X, double t) const {
    return expression[c] ? expression[c](X, t) : value[c] * scale(t);
  }
  // Its rate d/dt, for the power of the condition's reaction: a central difference (forward at
  // t = 0, where a time function starts).
  double prescribedRate(int c, const Eigen::Vector3d &X, double t) const {
    const double h = 1e-7 * std::max(1.0, std::abs(t));
    if (t < h) return (prescribed(c, X, t + h) - prescribed(c, X, t)) / h;
    return (prescribed(c, X, t + h) - prescribed(c, X, t - h)) / (2.0 * h);
  }
};

// A dead traction (force per reference area) on a face set, scaled in time.
struct DeadTractionLoad {
  std::string name;
  std::vector<mesh::ElementFace> faces;
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
  TimeFunction scale = TimeFunction::constant();
};

// A dead body force rho a on a set of elements (gravity: a = g), scaled in time; rho is the
// material's density.
struct BodyForceLoad {
  std::string name;
  std::vector<mesh::ElementId> elements; // sorted
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero(); // [m/s^2]
  bool gravity = false; // Loads/type = gravity (not a general body force): glossa zero-strain's load
  TimeFunction scale = TimeFunction::constant();
};

// A follower pressure sigma = -p I on the deformed faces of a set, p = p(X, t) (loads/PressureField).
struct FollowerPressureLoad {
  std::string name;
  std::vector<mesh::ElementFace> faces;
  loads::PressureField pressure = loads::PressureField::uniform(0.0);
  // When set, the pressures at each face's four Gauss points (index as `faces`, order as
  // loads::followerPressureGaussPoints) replace `pressure`: the airflow's, which the run sets
  // between solves (doc/airflow.md). Shared and mutable through a const scene, as
  // RigidContact::state, because it is the run's state.
  std::shared_ptr<std::vector<std::array<double, 4>>> given;
};

// How a contact's condition g >= 0 is enforced (doc/contact.md, "Penalty and augmented Lagrangian").
enum class ContactEnforcement { penalty, augmentedLagrangian };

// Contact of a face set with a rigid obstacle, frictionless, with Coulomb friction or tied
// (contact/FaceContact, doc/contact.md) or, when `pair` is set, frictionless with a face set of the
// body (contact/PairContact: a deformable pair, or the face set itself, self-contact); `faces` are
// then the slave faces, whose contact points are searched against the master faces.
struct RigidContact {
  std::string name;
  std::vector<mesh::ElementFace> faces;
  std::shared_ptr<const contact::Obstacle> obstacle; // null for a deformable pair
  std::shared_ptr<const contact::DeformablePair> pair;
  // The same obstacle when it moves in time (null: at rest): the run sets its time where the
  // loads get theirs (the model evaluator's time, each evaluation's). Mutable through a const
  // scene, as `state`.
  std::shared_ptr<contact::MovingObstacle> motion;
  contact::ContactSettings settings;
  ContactEnforcement enforcement = ContactEnforcement::augmentedLagrangian;
  double gapTolerance = 0; // [m]: the Uzawa loop's bound on the largest gap error (augmented Lagrangian)
  // Per face of `faces` (index as there): the multipliers, gaps and pressures. Shared and mutable
  // through a const scene because it is the run's state, not the model's: the assembly reads the
  // trial multipliers, the Uzawa loop records the converged gaps and updates them, the stepper
  // commits, rolls back and checkpoints them, as the muscle history. Each rank fills the entries
  // of the faces of its own elements.
  std::shared_ptr<contact::ContactState> state;
  bool augmented() const { return enforcement == ContactEnforcement::augmentedLagrangian; }
  bool deformable() const { return pair != nullptr; }
};

// How elements are shared out among ranks: the built-in coordinate bisection (mesh/Partition) or
// Zoltan2's geometric partitioners (assembly/ZoltanPartition).
enum class Partitioner { coordinateBisection, zoltan2MultiJagged, zoltan2Rcb };

struct Scene {
  mesh::HexMesh mesh;
  Partitioner partitioner = Partitioner::coordinateBisection;
  // The tissues (at least one: the Material section's) and each element's. A tissue's matrix
  // is the whole material where no fibres are; its shear modulus scales its elements' penalty.
  // Fibres and muscle groups (with their element's matrix in their point laws) are in `muscles`.
  std::vector<Tissue> tissues;
  std::vector<int> elementTissue; // per mesh element; empty: every element is tissues[0]
  MuscleArchitecture muscles;
  ElementFormulation formulation = ElementFormulation::Q1P0;
  bool symmetricTangent = true; // CG applies; false selects GMRES when the deck says auto
  std::vector<DirichletCondition> dirichlet;
  std::vector<DeadTractionLoad> tractions;
  std::vector<BodyForceLoad> bodyForces;
  std::vector<FollowerPressureLoad> pressures;
  int airflowLoad = -1; // the pressure load the airflow sets (index into `pressures`); -1: no airflow
  std::vector<RigidContact> contacts;
  std::vector<std::string> tracedPoints; // names in mesh.namedPoints, in deck order
  // What the mesh reader changed on the way in (ImportedMesh::notes), for the run to print.
  std::vector<std::string> meshNotes;

  const Tissue &tissueOf(std::size_t element) const {
    return tissues[elementTissue.empty() ? 0 : static_cast<std::size_t>(elementTissue[element])];
  }
};

// Makes `reference` the scene's reference node positions (a zero-strain configuration, §8.1): the
// mesh keeps the positions it had as the imaged geometry (mesh::replaceReferenceNodes) and the
// external muscles' insertions move with their nodes, while their bony origins stay.
void useReferenceNodes(Scene &scene, std::vector<Eigen::Vector3d> reference);

// The nodes each slave face of a deformable pair couples in the tangent (its own and its
// candidate master faces'), with the element holding the face: the rank owning that element
// ghosts them, and the matrix graph, built once, holds their couplings (doc/contact.md).
struct NodeCoupling {
  mesh::ElementId element = 0;
  std::vector<mesh::NodeId> nodes;
};
std::vector<NodeCoupling> contactCouplings(const Scene &scene);

} // namespace glossa::model
