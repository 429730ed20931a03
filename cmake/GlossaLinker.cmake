# Links with gold when the toolchain has it (Debian's binutils ships ld.gold beside ld.bfd): some
# 50 executables each link the solver's static libraries against about 110 shared libraries of
# Trilinos, MPI and HDF5, and gold reads them faster: glossa, test_hertz and unit_solvers_run
# each linked in 1.0-1.1 s with gold against 3.7-4.2 s with ld.bfd (doc/developing.md, "Build time").
# GLOSSA_LINKER=default keeps the compiler's own linker.
set(GLOSSA_LINKER gold CACHE STRING "Linker passed to the compiler as -fuse-ld= (default: the compiler's own)")
if(NOT GLOSSA_LINKER STREQUAL "default")
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=${GLOSSA_LINKER}" GLOSSA_HAS_LINKER_${GLOSSA_LINKER})
  if(GLOSSA_HAS_LINKER_${GLOSSA_LINKER})
    add_link_options(-fuse-ld=${GLOSSA_LINKER})
  else()
    message(STATUS "ld.${GLOSSA_LINKER} not found: linking with the compiler's own linker")
  endif()
endif()
