# Writes OUTPUT_C and OUTPUT_H holding each GLSL file of SHADERS (a
# ;-list) as a C string named fgg_shader_<folder>_<file name without
# extension>: gpu/shaders/field/dot.glsl is fgg_shader_field_dot.
# A shader may take in a piece that several share with a line
#   #include "name.inc.glsl"
# (a file of its folder): the piece's text replaces the line here, since
# GLSL has no #include. Pieces (*.inc.glsl) are not embedded by themselves.
# Run as a script: cmake -DSHADERS=... -DOUTPUT_C=... -DOUTPUT_H=... -P
# SHADERS may also be |-separated (a ;-list does not survive a COMMAND line).
string(REPLACE "|" ";" SHADERS "${SHADERS}")
set(c "/* Generated from gpu/shaders by cmake/EmbedShaders.cmake. */\n#include \"gpu_shaders.h\"\n")
set(h "/* Generated from gpu/shaders by cmake/EmbedShaders.cmake. */\n#ifndef FULGUR_GPU_SHADERS_H\n#define FULGUR_GPU_SHADERS_H\n")
foreach(file IN LISTS SHADERS)
  if(file MATCHES "\\.inc\\.glsl$")
    continue()
  endif()
  get_filename_component(dir "${file}" DIRECTORY)
  get_filename_component(folder "${dir}" NAME)
  get_filename_component(name "${file}" NAME_WE)
  set(name "${folder}_${name}")
  file(READ "${file}" text)
  string(REGEX MATCHALL "#include \"[^\"]+\"" includes "${text}")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "#include \"([^\"]+)\"" "\\1" piece "${line}")
    if(NOT piece MATCHES "\\.inc\\.glsl$" OR NOT EXISTS "${dir}/${piece}")
      message(FATAL_ERROR "${file}: ${line}: not a piece (name.inc.glsl) of ${dir}")
    endif()
    file(READ "${dir}/${piece}" piece_text)
    string(REPLACE "${line}\n" "${piece_text}" text "${text}")
  endforeach()
  string(REPLACE "\\" "\\\\" text "${text}")
  string(REPLACE "\"" "\\\"" text "${text}")
  string(REPLACE "\n" "\\n\"\n    \"" text "${text}")
  string(APPEND c "\nconst char fgg_shader_${name}[] =\n    \"${text}\";\n")
  string(APPEND h "extern const char fgg_shader_${name}[];\n")
endforeach()
string(APPEND h "#endif\n")
file(WRITE "${OUTPUT_C}.tmp" "${c}")
file(WRITE "${OUTPUT_H}.tmp" "${h}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT_C}.tmp" "${OUTPUT_C}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT_H}.tmp" "${OUTPUT_H}")
