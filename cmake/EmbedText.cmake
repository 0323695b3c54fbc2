cmake_minimum_required(VERSION 3.25)
# Script mode: writes OUTPUT, a header that holds each of INPUTS (a |-separated list of files) as an
# inline constexpr std::string_view named k<Stem><Ext> (combination.frag -> kCombinationFrag;
# '_' and '-' separate words).
# Invoked by voxref_embed_text() at build time so that editing a shader rebuilds its users.
string(REPLACE "|" ";" INPUTS "${INPUTS}")
set(content "// Generated from ${INPUTS} by cmake/EmbedText.cmake. Do not edit.\n#pragma once\n#include <string_view>\nnamespace ${NAMESPACE} {\n")
foreach(file IN LISTS INPUTS)
  file(READ "${file}" text)
  get_filename_component(stem "${file}" NAME_WE)
  get_filename_component(ext "${file}" LAST_EXT)
  string(SUBSTRING "${ext}" 1 -1 ext)
  set(ident "")
  foreach(part IN ITEMS ${stem} ${ext})
    string(REGEX REPLACE "[-_]" ";" words "${part}")  # shader-interface.md -> kShaderInterfaceMd
    foreach(word IN LISTS words)
      string(SUBSTRING "${word}" 0 1 first)
      string(TOUPPER "${first}" first)
      string(SUBSTRING "${word}" 1 -1 rest)
      string(APPEND ident "${first}${rest}")
    endforeach()
  endforeach()
  string(APPEND content "inline constexpr std::string_view k${ident} = R\"voxref_text(${text})voxref_text\";\n")
endforeach()
string(APPEND content "}  // namespace ${NAMESPACE}\n")
file(WRITE "${OUTPUT}.tmp" "${content}")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
