# Helpers shared by every layer's CMakeLists.txt.

# Warnings for the project's own code.
function(voxref_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter)
endfunction()

# reference/ and emulation/ must compute bit-exact results: no contraction of a*b+c into a fused
# multiply-add, no fast-math, no -march=native (docs/design.md, Conventions); x86-64 evaluates in SSE
# registers, so there is no excess precision either. Where an emulated driver
# fuses, the code calls std::fma explicitly.
function(voxref_exact_arithmetic target)
  target_compile_options(${target} PRIVATE -ffp-contract=off -fno-fast-math)
endfunction()

# The include folder of a target: <build>/include/<target>/ holds one link, <FOLDER> (a path from
# the repository root, "reference" or "conformance/framework"), to that folder of the sources.
# Headers are included by their path from the repository root ("reference/common/volume.h"), and
# a target sees the headers of its own folder and of what it links, nothing else: an include of a
# layer it may not use fails to compile (docs/design.md, "Layers"; tests/layering).
function(voxref_include_folder target scope folder)
  set(root "${PROJECT_BINARY_DIR}/include/${target}")
  get_filename_component(parent "${root}/${folder}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  if(NOT IS_SYMLINK "${root}/${folder}")
    file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${folder}" "${root}/${folder}" SYMBOLIC)
  endif()
  target_include_directories(${target} ${scope} "${root}")
endfunction()

# A static library of one folder: voxref_library(target FOLDER <path from the root> SOURCES ...).
# Sources are listed by the caller; headers live beside them.
function(voxref_library target)
  cmake_parse_arguments(ARG "" "FOLDER" "SOURCES" ${ARGN})
  if(NOT ARG_FOLDER OR NOT ARG_SOURCES)
    message(FATAL_ERROR "voxref_library(${target} FOLDER <folder> SOURCES ...)")
  endif()
  add_library(${target} STATIC ${ARG_SOURCES})
  voxref_include_folder(${target} PUBLIC "${ARG_FOLDER}")
  voxref_warnings(${target})
endfunction()

# Embeds text files (shaders) into a generated header `<binary dir>/<HEADER>` and adds it to
# TARGET's include path: voxref_embed_text(voxref_gpu HEADER gpu/shader_sources.h
# NAMESPACE voxref::gpu::shaders FILES shaders/a.frag ...).
function(voxref_embed_text target)
  cmake_parse_arguments(ARG "" "HEADER;NAMESPACE" "FILES" ${ARGN})
  set(inputs "")
  foreach(f IN LISTS ARG_FILES)
    list(APPEND inputs "${CMAKE_CURRENT_SOURCE_DIR}/${f}")
  endforeach()
  set(output "${PROJECT_BINARY_DIR}/generated/${ARG_HEADER}")
  string(JOIN "|" joined ${inputs})  # ';' would split the command argument
  add_custom_command(OUTPUT "${output}"
    COMMAND ${CMAKE_COMMAND} "-DINPUTS=${joined}" "-DOUTPUT=${output}" "-DNAMESPACE=${ARG_NAMESPACE}"
            -P "${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake"
    DEPENDS ${inputs} "${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake"
    COMMENT "Embedding ${ARG_HEADER}" VERBATIM)
  target_sources(${target} PRIVATE "${output}")
  target_include_directories(${target} PRIVATE "${PROJECT_BINARY_DIR}/generated")
endfunction()
