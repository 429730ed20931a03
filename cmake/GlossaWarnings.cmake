# Project-wide compiler settings.
add_library(glossa_warnings INTERFACE)
target_compile_options(glossa_warnings INTERFACE -Wall -Wextra -Wno-unused-parameter)
add_library(glossa::warnings ALIAS glossa_warnings)
