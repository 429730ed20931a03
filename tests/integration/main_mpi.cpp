// GoogleTest main for tests that need MPI and Kokkos initialised, and the world communicator
// it sets up (WorldComm.hpp).
#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include "WorldComm.hpp"
#include "app/SingletonSession.hpp"

Teuchos::RCP<const Teuchos::Comm<int>> glossa::test::worldComm() { return Tpetra::getDefaultComm(); }

int main(int argc, char **argv) {
  glossa::app::separateIsolatedSingletonSession();
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Only rank 0 reports, so ctest's output stays readable under mpiexec.
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto &listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
