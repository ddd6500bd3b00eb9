# Embeds a text file (a GLSL shader) in a C++ header as `inline constexpr char NAME[]`, so
# shaders live in .glsl files and still ship inside the program (STYLE: no long string
# literals in C++). Run at build time:
#   cmake -DINPUT=file.glsl -DOUTPUT=file.glsl.hpp -DNAME=kSymbol -P embed_text.cmake
file(READ "${INPUT}" text)
string(FIND "${text}" ")embedded\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )embedded\"")
endif()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by cmake/embed_text.cmake; edit the source file.\n"
  "#pragma once\n"
  "inline constexpr char ${NAME}[] = R\"embedded(${text})embedded\";\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
