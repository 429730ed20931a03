# Unity builds: files compiled together, so that the headers they share are read once a unit.
# - The libraries whose files include Tpetra, Thyra, NOX or Teuchos compile in batches of 8 files:
#   those headers cost 10 to 15 s a unit. A file in such a library keeps its file-local helpers'
#   names distinct from the other files'.
# - A unit-test executable whose files define no two helpers alike compiles as one unit: most of
#   a small test file's time is gtest's and Eigen's headers.
# Figures in doc/developing.md, "Build time". -DGLOSSA_UNITY_LIBRARIES=OFF and
# -DGLOSSA_UNITY_TESTS=OFF compile each file alone again, which recompiles less after an edit.
option(GLOSSA_UNITY_LIBRARIES "Compile the Trilinos-heavy libraries in batches of 8 files" ON)
option(GLOSSA_UNITY_TESTS "Compile the unit-test executables that allow it as one unit each" ON)

# `target` in batches of `batch` files (0: all in one) when the option named `switch` is on.
function(glossa_unity target switch batch)
  if(${switch})
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch})
  endif()
endfunction()
function(glossa_unity_library target)
  glossa_unity(${target} GLOSSA_UNITY_LIBRARIES 8)
endfunction()
function(glossa_unity_test target)
  glossa_unity(${target} GLOSSA_UNITY_TESTS 0)
endfunction()
