#pragma once
// A load as one contribution to the assembly: what it subtracts from the residual
// f = f_int - f_ext and, with a tangent, from K, on this rank's faces, elements or nodes. The
// Assembler turns the scene's loads into a list of them (loadContributions) and walks it for the
// residual and tangent, the load residual, the external-force norm and the nodal forces of
// reactions and resultants, each pass taking the kinds it needs. A new kind of load is a new
// contribution with its kernel in src/loads, not a new Assembler method.

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "assembly/DofLayout.hpp"
#include "assembly/TpetraTypes.hpp"
#include "loads/DeadTraction.hpp"
#include "model/MuscleHistory.hpp"
#include "model/Scene.hpp"

namespace glossa::assembly {

// Where a contribution reads and writes in one pass.
struct LoadTarget {
  const model::Scene &scene;
  const DofLayout &layout;
  const Map &overlapMap;
  const std::vector<char> &constrained; // per mesh dof 3 n + c: fixed by a Dirichlet condition
  Teuchos::ArrayRCP<const double> u;    // the overlap displacement
  Teuchos::ArrayRCP<double> *residual;  // the overlap residual; null: evaluation only
  FEMatrix *K = nullptr;                // null: no tangent
  bool constrainedToo = false;          // also at fixed dofs (the nodal forces of reactions)

  Eigen::Vector3d displacement(mesh::NodeId node) const;
  // residual -= f and K -= df/du for a block of n <= 8 nodes (df: 3n x 3n, column-major; null
  // for a load that does not depend on u). Fixed rows are skipped unless constrainedToo, and the
  // tangent's fixed rows and columns always.
  void subtract(const mesh::NodeId *nodes, int n, const double *f, const double *df) const;
};

// A face's nodes (outward right-hand order), their reference positions and their displacements
// at a target: what every face load and contact reads.
struct FaceAtTarget {
  std::array<mesh::NodeId, 4> nodes;
  loads::FaceNodes X, u;
  loads::FaceNodes current() const { return X + u; }
};
FaceAtTarget faceAt(const LoadTarget &target, const mesh::ElementFace &face);

class LoadContribution {
public:
  enum class Kind {
    dead,     // independent of u (tractions, body forces): also the scale of the Newton tolerance
    follower, // depends on u (follower pressures, rigid contacts, external muscles)
    support   // elastic supports: springs whose force is their condition's reaction, not a load
  };
  virtual ~LoadContribution() = default;
  virtual Kind kind() const = 0;
  // Acts through the boundary (tractions, pressures, external muscles): left out of face-set
  // resultants, which sum internal less body forces.
  virtual bool onSurface() const = 0;
  // Subtracts the load at time t from the target; false if it cannot be evaluated at the
  // target's displacement (an external fibre's local solve failed on this rank).
  virtual bool addTo(const LoadTarget &target, double time) const = 0;
};

// The external muscles' fibres (paper §5, eq. 16): a follower load, and at a converged state the
// history's trial lambda_c and each group's length-weighted stretch.
class ExternalMuscleForces final : public LoadContribution {
public:
  ExternalMuscleForces(const model::Scene &scene, const model::MuscleHistory &history)
      : scene_(scene), history_(history) {}
  Kind kind() const override { return Kind::follower; }
  bool onSurface() const override { return true; }
  bool addTo(const LoadTarget &target, double time) const override;
  // The fibres at the target's displacement: their forces subtracted if the target has a
  // residual; with `trial`, their new lambda_c written to its trial values; with `stretch` (3 per
  // group), lambda_f L_0, lambda_c L_0 and L_0 added. False if a local solve failed on this rank.
  bool evaluate(const LoadTarget &target, model::MuscleHistory *trial, std::vector<double> *stretch) const;

private:
  const model::Scene &scene_;
  const model::MuscleHistory &history_; // activation, step and committed lambda_c
};

// One follower pressure alone, as the scene's list holds it (a pressure whose own residual is
// wanted: the airflow's per section, solvers/run/AirflowCoupling).
std::unique_ptr<LoadContribution> followerPressureContribution(const model::FollowerPressureLoad &load);

// The scene's loads in assembly order: dead tractions, body forces, follower pressures,
// contacts (rigid and deformable), external muscles (if any), elastic supports. `externalMuscles` receives the external muscles' entry (or
// null) for the muscle history's update.
std::vector<std::unique_ptr<LoadContribution>> loadContributions(const model::Scene &scene,
                                                                 const model::MuscleHistory &history,
                                                                 const ExternalMuscleForces **externalMuscles);

} // namespace glossa::assembly
