cmake_minimum_required(VERSION 3.25)
# Script mode (ctest `layering`): the #include lines of every layer respect docs/design.md's rules,
# the same rules target_link_libraries enforces at link time:
#   reference/   includes only reference/ (and the standard library, GLM)
#   emulation/   includes reference/ and emulation/
#   gpu/         includes reference/ and gpu/, never emulation/
#   fixtures/    includes reference/ and fixtures/ (and Embree), never emulation/, gpu/, GL or file formats
#   conformance/ anything
# SOURCE_DIR: the repository root.
set(rules
  "reference|emulation/|gpu/|conformance/|GL/|EGL/|OpenEXR|OpenImageIO|nlohmann|CLI/"
  "emulation|gpu/|conformance/|GL/|EGL/|OpenEXR|OpenImageIO|nlohmann|CLI/"
  "gpu|emulation/|conformance/|OpenEXR|OpenImageIO|nlohmann|CLI/"
  "fixtures|emulation/|gpu/|conformance/|GL/|EGL/|OpenEXR|OpenImageIO|nlohmann|CLI/")
set(violations "")
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  list(POP_FRONT parts layer)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${layer}/*.h" "${SOURCE_DIR}/${layer}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" includes REGEX "^#include")
    foreach(line IN LISTS includes)
      foreach(forbidden IN LISTS parts)
        string(FIND "${line}" "${forbidden}" at)
        if(NOT at EQUAL -1)
          file(RELATIVE_PATH rel "${SOURCE_DIR}" "${f}")
          list(APPEND violations "${rel}: ${line} (${layer}/ must not include ${forbidden})")
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()
if(violations)
  string(REPLACE ";" "\n" text "${violations}")
  message(FATAL_ERROR "layering violations:\n${text}")
endif()
message("layering: reference, emulation, gpu and fixtures include only what docs/design.md allows")
