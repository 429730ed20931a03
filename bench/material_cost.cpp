// Cost of one point-law evaluation, of one element kernel call, and of the element work of one
// assembly of Cook's membrane (32 x 32 x 1 elements) with the passive and the active muscle law
// (Google Benchmark; the scatter into Tpetra does not depend on the law and is left out). Run on
// demand: build/bench_material_cost --benchmark_out=bench/results/material_cost.json
// (see bench/README.md). Medians over repetitions: --benchmark_repetitions=5.
#include <memory>
#include <random>

#include <benchmark/benchmark.h>

#include "fem/Q1P0Element.hpp"
#include "materials/ContractileCurveSets.hpp"
#include "materials/FibreReinforcedMaterial.hpp"
#include "materials/FungIsotropic.hpp"
#include "materials/MuscleMaterial.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/ParallelElement.hpp"
#include "mesh/CookMembraneGenerator.hpp"
#include "model/TissuePointLaw.hpp"

using namespace glossa;

namespace {
Eigen::Matrix3d sampleF() {
  Eigen::Matrix3d F;
  F << 1.12, 0.03, -0.02, 0.01, 0.95, 0.04, -0.03, 0.02, 0.94;
  return F;
}

std::vector<Eigen::Vector3d> threeDirections() {
  return {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
}

void run(benchmark::State &state, const materials::IsochoricMaterial &m) {
  const Eigen::Matrix3d F = sampleF();
  for (auto _ : state) benchmark::DoNotOptimize(m.evaluate(F));
}
} // namespace

static void NeoHookean(benchmark::State &s) { run(s, materials::NeoHookean(80e6)); }
static void FungMatrix(benchmark::State &s) { run(s, materials::FungIsotropic::muscleMatrix()); }
static void PassiveThreeFamilies(benchmark::State &s) {
  const materials::FibreReinforcedMaterial m(std::make_shared<materials::FungIsotropic>(materials::FungIsotropic::muscleMatrix()),
                                             materials::equalFractionFamilies(threeDirections()),
                                             std::make_shared<materials::ParallelElement>(materials::ParallelElement::tableI()));
  run(s, m);
}
static void ActiveMuscleThreeFamilies(benchmark::State &s) {
  std::vector<materials::MuscleMaterial::Family> families;
  for (const auto &f : materials::equalFractionFamilies(threeDirections()))
    families.push_back({f, materials::HillMuscleFibre::tableI(1.0, materials::physiologicalCurves())});
  const materials::MuscleMaterial m(std::make_shared<materials::FungIsotropic>(materials::FungIsotropic::muscleMatrix()),
                                    families);
  materials::MusclePointInput in;
  in.F = sampleF();
  in.dt = 5e-3;
  in.alpha = materials::FamilyValues::Constant(3, 0.5);
  in.lambdaCOld = m.initialLambdaC();
  for (auto _ : s) benchmark::DoNotOptimize(m.evaluate(in));
}
static void Q1P0ElementTangent(benchmark::State &s) {
  fem::NodeMatrix X, u;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> d(-1e-5, 1e-5);
  for (int a = 0; a < 8; ++a) X.row(a) = 0.5e-3 * (fem::hexNodeXi(a).array() + 1.0).matrix().transpose();
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) u(a, i) = d(rng);
  const materials::NeoHookean iso(80e6);
  const materials::VolumetricEnergy vol(materials::VolumetricEnergy::Form::SimoTaylor, 8e9);
  const auto base = fem::mixedBase(X, u, nullptr, vol, 0.0);
  for (auto _ : s) benchmark::DoNotOptimize(fem::evaluateQ1P0Mixed(X, u, base, iso, vol, 0.0, false));
}

// Element residuals and tangents over Cook's membrane (32 x 32 x 1, 1024 elements) at a shear
// deformation u = (0, 0.05 x, 0): one assembly's element work. The muscle law has three active
// families (alpha = 0.5) with a lambda_c history per point, as a scene evaluates it.
static void CookAssemblyElementWork(benchmark::State &s) {
  const mesh::HexMesh cook = mesh::generateCookMembrane(32, 1, 1.0, 1e-3);
  const materials::VolumetricEnergy vol(materials::VolumetricEnergy::Form::SimoTaylor, 2e5);
  const materials::FungIsotropic matrix = materials::FungIsotropic::muscleMatrix();
  std::vector<materials::MuscleMaterial::Family> families;
  for (const auto &f : materials::equalFractionFamilies(threeDirections()))
    families.push_back({f, materials::HillMuscleFibre::tableI(1.0, materials::physiologicalCurves())});
  const materials::MuscleMaterial muscle(std::make_shared<materials::FungIsotropic>(matrix), families);
  const materials::FamilyDirections N = materials::FamilyDirections::Identity(3, 3);
  const materials::FamilyValues alpha = materials::FamilyValues::Constant(3, 0.5);
  const std::vector<double> lambdaC(24, 0.999);
  std::array<const double *, 8> history;
  for (int q = 0; q < 8; ++q) history[q] = &lambdaC[3 * q];
  const fem::UniformPointLaw passive(matrix);
  const model::TissuePointLaw active(muscle, N, alpha, 5e-3, history);
  const fem::QuadraturePointLaw &law = s.range(0) ? static_cast<const fem::QuadraturePointLaw &>(active) : passive;
  std::vector<fem::NodeMatrix> X, u;
  for (std::size_t e = 0; e < cook.numElements(); ++e) {
    X.push_back(cook.elementCoordinates(static_cast<mesh::ElementId>(e)));
    fem::NodeMatrix ue = fem::NodeMatrix::Zero();
    ue.col(1) = 0.05 * X.back().col(0);
    u.push_back(ue);
  }
  for (auto _ : s)
    for (std::size_t e = 0; e < X.size(); ++e) benchmark::DoNotOptimize(fem::evaluateQ1P0(X[e], u[e], law, vol, 0.0));
  s.counters["elements"] = static_cast<double>(X.size());
}

BENCHMARK(NeoHookean);
BENCHMARK(FungMatrix);
BENCHMARK(PassiveThreeFamilies);
BENCHMARK(ActiveMuscleThreeFamilies);
BENCHMARK(Q1P0ElementTangent);
BENCHMARK(CookAssemblyElementWork)->ArgName("active_muscle")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
