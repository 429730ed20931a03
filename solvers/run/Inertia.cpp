#include "solvers/run/Inertia.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "assembly/Assembler.hpp"
#include "io/deck/SpaceTimeExpression.hpp"
#include "model/Scene.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/stepping/BackwardEuler.hpp"

namespace glossa::solvers {

using assembly::FEMatrix;
using assembly::Vector;

namespace {

// K += c B for two matrices on the Assembler's graph (the same local pattern). Collective.
void addScaled(FEMatrix &K, double c, const FEMatrix &B) {
  if (c == 0.0) return;
  K.beginModify();
  {
    auto k = K.getLocalMatrixHost();
    const auto b = B.getLocalMatrixHost();
    if (k.values.extent(0) != b.values.extent(0) || k.graph.entries.data() != b.graph.entries.data())
      throw std::logic_error("Inertia: the tangent and the mass matrix have different patterns");
    for (std::size_t i = 0; i < k.values.extent(0); ++i) k.values(i) += c * b.values(i);
  }
  K.endModify();
}

// Solves (M + I_c) x = b, I_c the identity at the constrained dofs (where M, the tangent's mass,
// is empty), by conjugate gradients preconditioned with the diagonal: M is symmetric positive
// definite at the free dofs and its condition number does not grow with the mesh (a cube's
// trilinear element matrix has 27: the 1D element's 3 cubed), so a few tens of iterations reach
// round-off. Collective.
void solveMass(const FEMatrix &M, const Vector &constrained, const Vector &b, Vector &x) {
  const auto map = b.getMap();
  Vector inverseDiagonal(map), r(b, Teuchos::Copy), z(map), p(map), Ap(map);
  M.getLocalDiagCopy(inverseDiagonal);
  inverseDiagonal.update(1.0, constrained, 1.0);
  inverseDiagonal.reciprocal(inverseDiagonal);
  const auto apply = [&](const Vector &in, Vector &out) {
    M.apply(in, out);
    out.elementWiseMultiply(1.0, constrained, in, 1.0);
  };
  x.putScalar(0.0);
  const double bNorm = b.norm2();
  if (bNorm == 0.0) return;
  z.elementWiseMultiply(1.0, inverseDiagonal, r, 0.0);
  p.assign(z);
  double rz = r.dot(z);
  for (int k = 0; k < 1000 && r.norm2() > 1e-14 * bNorm; ++k) {
    apply(p, Ap);
    const double alpha = rz / p.dot(Ap);
    x.update(alpha, p, 1.0);
    r.update(-alpha, Ap, 1.0);
    z.elementWiseMultiply(1.0, inverseDiagonal, r, 0.0);
    const double rzNext = r.dot(z);
    p.update(1.0, z, rzNext / rz);
    rz = rzNext;
  }
  if (!(r.norm2() <= 1e-10 * bNorm))
    throw std::runtime_error("Inertia: the initial acceleration's mass solve did not converge");
}

// The deck's initial velocity at the free dofs and the supports' rates at the constrained ones.
void initialVelocity(const assembly::Assembler &assembler, const DynamicsParameters &p, Vector &v) {
  const model::Scene &scene = assembler.scene();
  const auto &layout = assembler.layout();
  const io::SpaceTimeExpression vx(p.initialVelocity[0]), vy(p.initialVelocity[1]), vz(p.initialVelocity[2]);
  const io::SpaceTimeExpression *component[3] = {&vx, &vy, &vz};
  {
    auto data = v.getDataNonConst(0);
    for (std::size_t k = 0; k < layout.ownedNodes.size(); ++k) {
      const Eigen::Vector3d &X = scene.mesh.nodes[layout.ownedNodes[k]];
      for (int c = 0; c < 3; ++c) data[3 * k + c] = (*component[c])(X.x(), X.y(), X.z(), 0.0);
    }
  }
  assembler.zeroConstrainedDofs(v);
  for (const auto &bc : scene.dirichlet) {
    if (bc.elastic()) continue;
    for (mesh::NodeId n : bc.nodes) {
      if (layout.nodeOwner[n] != layout.rank) continue;
      for (int c = 0; c < 3; ++c)
        if (bc.fixed[c]) v.replaceGlobalValue(layout.dof(n, c), bc.prescribedRate(c, scene.mesh.nodes[n], 0.0));
    }
  }
}

} // namespace

Inertia::Inertia(const assembly::Assembler &assembler, const DynamicsParameters &parameters, const StepState &initial)
    : assembler_(assembler), parameters_(parameters),
      scheme_(parameters.integrator == Integrator::energyConserving ? 1.0 : parameters.spectralRadius) {
  using Constrained = assembly::Assembler::ConstrainedDofs;
  mass_ = assembler_.createMatrix();
  massTangent_ = assembler_.createMatrix();
  assembler_.assembleMass(*mass_, parameters_.mass, Constrained::keep);
  assembler_.assembleMass(*massTangent_, parameters_.mass, Constrained::zeroed);
  const auto map = initial.u.getMap();
  if (parameters_.rayleighStiffness > 0.0) {
    stiffness0_ = assembler_.createMatrix();
    Vector scratch(map);
    if (!assembler_.assemble(initial.u, 0.0, initial.lambda, nullptr, &scratch, stiffness0_.get()).valid)
      throw std::runtime_error("Inertia: the initial state has an inverted element");
  }
  u_ = std::make_unique<Vector>(initial.u, Teuchos::Copy);
  v_ = std::make_unique<Vector>(map);
  a_ = std::make_unique<Vector>(map);
  g_ = std::make_unique<Vector>(map);
  initialVelocity(assembler_, parameters_, *v_);
  balanceForces(initial, 0.0, *v_, *g_);
  // M a_0 = -g_0 at the free dofs; a_0 = 0 at the constrained ones (a prescribed motion starts
  // without acceleration, and Newmark's updates follow its values from the first step on).
  Vector free(map), constrained(map), rhs(*g_, Teuchos::Copy);
  free.putScalar(1.0);
  assembler_.zeroConstrainedDofs(free);
  constrained.putScalar(1.0);
  constrained.update(-1.0, free, 1.0);
  rhs.scale(-1.0);
  solveMass(*massTangent_, constrained, rhs, *a_);
  if (parameters_.integrator == Integrator::energyConserving) {
    // Every condensed Q1-P0 element without muscle fibres (whose active stress stores no energy).
    const model::Scene &scene = assembler_.scene();
    const auto &elements = assembler_.layout().localElements;
    std::vector<char> corrected(elements.size(), 0);
    for (std::size_t i = 0; i < elements.size(); ++i)
      corrected[i] = scene.formulation == model::ElementFormulation::Q1P0 &&
                     !(scene.muscles.hasFibres() && scene.muscles.elementRegion[elements[i]] >= 0);
    energyConserving_ = std::make_unique<EnergyConservingForces>(std::move(corrected), 1.0 / (1.0 - scheme_.alphaF()));
    recordElements(initial);
  }
}

void Inertia::recordElements(const StepState &state) {
  if (!energyConserving_) return;
  assembler_.forEachElement(
      state.u, state.lambda, [&](std::size_t i) { return energyConserving_->corrects(i); },
      [&](std::size_t i, const fem::NodeMatrix &ue, const fem::Q1P0Result &r, const materials::VolumetricEnergy &law) {
        energyConserving_->record(i, ue, state.lambda[i], r, law);
      });
}

Inertia::~Inertia() = default;

void Inertia::beginStep(double dt) {
  step_ = parameters_.integrator == Integrator::backwardEuler ? backwardEulerStep(dt) : scheme_.step(dt);
}

void Inertia::newmark(const Vector &u, Vector &a, Vector &v) const {
  a.update(step_.c0, u, -step_.c0, *u_, 0.0);
  a.update(-step_.c1, *v_, -step_.c2, *a_, 1.0);
  v.update(1.0, *v_, step_.vOld, *a_, 0.0);
  v.update(step_.vNew, a, 1.0);
}

void Inertia::applyDamping(const Vector &x, Vector &y) const {
  y.putScalar(0.0);
  if (parameters_.rayleighMass > 0.0) {
    mass_->apply(x, y);
    y.scale(parameters_.rayleighMass);
  }
  if (stiffness0_.is_null()) return;
  Vector Kx(x.getMap());
  stiffness0_->apply(x, Kx);
  y.update(parameters_.rayleighStiffness, Kx, 1.0);
}

void Inertia::addTo(const Vector &u, Vector *f, FEMatrix *K) const {
  if (!(step_.dt > 0.0)) throw std::logic_error("Inertia: a step's terms asked for before the step began");
  if (f) {
    const auto map = u.getMap();
    Vector a(map), v(map), w(map), Mw(map), Cv(map);
    newmark(u, a, v);
    w.update(step_.newAcceleration, a, step_.oldAcceleration, *a_, 0.0);
    mass_->apply(w, Mw);
    applyDamping(v, Cv);
    Mw.update(1.0, Cv, step_.oldForces, *g_, 1.0);
    assembler_.zeroConstrainedDofs(Mw);
    f->update(1.0, Mw, 1.0);
  }
  if (K) {
    addScaled(*K, step_.massFactor + step_.dampingFactor * parameters_.rayleighMass, *massTangent_);
    if (!stiffness0_.is_null()) addScaled(*K, step_.dampingFactor * parameters_.rayleighStiffness, *stiffness0_);
  }
}

void Inertia::balanceForces(const StepState &state, double time, const Vector &v, Vector &g) const {
  if (!assembler_.assemble(state.u, time, state.lambda, nullptr, &g, nullptr).valid)
    throw std::runtime_error("Inertia: an inverted element in a converged state");
  Vector Cv(v.getMap());
  applyDamping(v, Cv);
  assembler_.zeroConstrainedDofs(Cv);
  g.update(1.0, Cv, 1.0);
}

void Inertia::commit(const StepState &state, double time) {
  const auto map = state.u.getMap();
  Vector a(map), v(map);
  newmark(state.u, a, v);
  balanceForces(state, time, v, *g_);
  u_->assign(state.u);
  v_->assign(v);
  a_->assign(a);
  recordElements(state);
}

double Inertia::kineticEnergy() const {
  Vector Mv(v_->getMap());
  mass_->apply(*v_, Mv);
  return 0.5 * v_->dot(Mv);
}

void Inertia::save(nlohmann::json &part) const {
  part["inertia"] = {{"u", ownedValues(*u_)}, {"v", ownedValues(*v_)}, {"a", ownedValues(*a_)}, {"g", ownedValues(*g_)}};
}

void Inertia::restore(const nlohmann::json &part, const StepState &committed) {
  const nlohmann::json &j = part.at("inertia");
  assignOwnedValues(*u_, j.at("u"), "dynamic displacement");
  assignOwnedValues(*v_, j.at("v"), "velocity");
  assignOwnedValues(*a_, j.at("a"), "acceleration");
  assignOwnedValues(*g_, j.at("g"), "dynamic forces");
  recordElements(committed);
}

} // namespace glossa::solvers
