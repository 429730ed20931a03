#pragma once
// The preconditioner families Stratimikos builds by name ("MueLu", "FROSch", "Ifpack2"), each
// registered with a builder by a unit of its own: their template instantiations are most of the
// linear solver's compile time (FROSch alone over a minute), and in one unit they compiled one
// after another on one core while every later target waited for them (doc/developing.md, "Build
// time"). Apart, they compile side by side. MUMPS is registered beside them by
// LinearSolverFactory (its factory is Glossa's own, already a unit of its own).

namespace Stratimikos {
class DefaultLinearSolverBuilder;
}

namespace glossa::solvers {

// MueLu smoothed aggregation, "MueLu".
void registerMueLu(Stratimikos::DefaultLinearSolverBuilder &builder);
// FROSch two-level Schwarz, "FROSch".
void registerFrosch(Stratimikos::DefaultLinearSolverBuilder &builder);
// Ifpack2 alone (relaxation, Chebyshev, ILUT), "Ifpack2".
void registerIfpack2(Stratimikos::DefaultLinearSolverBuilder &builder);

} // namespace glossa::solvers
