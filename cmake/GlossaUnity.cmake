# Libraries whose files include Tpetra, Thyra, NOX or Teuchos compile in batches of 8 files (a
# unity build): those headers cost 10 to 15 s a unit, read once a batch instead of once a file
# (doc/developing.md, "Build time"). A file in such a library keeps its file-local helpers' names
# distinct from the other files'. -DGLOSSA_UNITY_LIBRARIES=OFF compiles each file alone again,
# which recompiles less after an edit to one.
option(GLOSSA_UNITY_LIBRARIES "Compile the Trilinos-heavy libraries in batches of 8 files" ON)
function(glossa_unity_library target)
  if(GLOSSA_UNITY_LIBRARIES)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
