#pragma once
// The communicator of every rank the test runs on, as main_mpi.cpp's Tpetra scope set it up.
// Declared here and defined beside that main so that the tests include Teuchos' communicator
// alone: Tpetra_Core.hpp pulls in Kokkos (155,000 preprocessed lines against Teuchos_Comm.hpp's
// 83,000), and there are some 30 test files.

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

namespace glossa::test {

// Tpetra::getDefaultComm(): the same object the solver's own Tpetra maps are built on.
Teuchos::RCP<const Teuchos::Comm<int>> worldComm();

} // namespace glossa::test
