# Wraps Debian 12's Trilinos 13.2 into one INTERFACE target, glossa::trilinos.
# Its exported targets carry link dependencies but neither include directories nor MPI
# (doc/developing.md), so the include paths go in here as SYSTEM to keep
# Trilinos' own warnings out of ours.
find_package(MPI REQUIRED COMPONENTS CXX)
find_package(Trilinos 13.2 REQUIRED COMPONENTS
  Teuchos Tpetra Belos MueLu Ifpack2 Amesos2 Stratimikos Thyra ThyraTpetraAdapters NOX ShyLU_DDFROSch Zoltan2 Teko)
message(STATUS "Trilinos ${Trilinos_VERSION} from ${Trilinos_DIR}")

add_library(glossa_trilinos INTERFACE)
target_include_directories(glossa_trilinos SYSTEM INTERFACE
  ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(glossa_trilinos INTERFACE
  ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)
add_library(glossa::trilinos ALIAS glossa_trilinos)

# Teuchos alone (ParameterList, XML) for the deck reader: much lighter than Tpetra.
add_library(glossa_teuchos INTERFACE)
target_include_directories(glossa_teuchos SYSTEM INTERFACE
  ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(glossa_teuchos INTERFACE trilinos_teuchosparameterlist trilinos_teuchosparser
  trilinos_teuchoscomm trilinos_teuchoscore trilinos_kokkoscore MPI::MPI_CXX)
add_library(glossa::teuchos ALIAS glossa_teuchos)
