# Helpers shared by every layer's CMakeLists.txt.

# Warnings for the project's own code.
function(voxref_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
endfunction()

# reference/ and emulation/ must compute bit-exact results: no contraction of a*b+c into a fused
# multiply-add, no fast-math, no -march=native (DESIGN.md, Conventions); x86-64 evaluates in SSE
# registers, so there is no excess precision either. Where an emulated driver
# fuses, the code calls std::fma explicitly.
function(voxref_exact_arithmetic target)
  target_compile_options(${target} PRIVATE -ffp-contract=off -fno-fast-math)
endfunction()

# A static library of one layer. Sources are listed by the caller; headers live beside them and
# are included by their path from the repository root ("reference/sparsegrid/combination.h").
function(voxref_library target)
  add_library(${target} STATIC ${ARGN})
  target_include_directories(${target} PUBLIC "${PROJECT_SOURCE_DIR}")
  voxref_warnings(${target})
endfunction()
