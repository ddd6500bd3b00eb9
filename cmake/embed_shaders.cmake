# lfd_embed_shaders(TARGET DIR): every shader stage in DIR (NAME.comp.glsl, NAME.vert.glsl,
# NAME.frag.glsl) becomes the generated header
# "<module>/shaders/NAME.EXT.glsl.hpp" (the path of DIR from the repository root) holding
# `inline constexpr char NAME_EXT_glsl[]`, added to TARGET's sources with the generated folder on
# its include path. Shaders stay .glsl files (STYLE: no long string literals in C++) and still
# ship inside the program; `#include "path"` inside them is resolved from the repository root with
# a `#line` per file (cmake/embed_shader.py; docs/gpu.md "Shaders and their contracts").
find_package(Python3 REQUIRED COMPONENTS Interpreter)

function(lfd_embed_shaders target dir)
  file(RELATIVE_PATH rel_dir ${PROJECT_SOURCE_DIR} ${dir})
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/generated)
  # Pieces (NAME.glsl, NAME_io.h) are only #included by stages.
  file(GLOB shader_files CONFIGURE_DEPENDS ${dir}/*.comp.glsl ${dir}/*.vert.glsl ${dir}/*.frag.glsl)
  set(headers)
  foreach(shader_path ${shader_files})
    get_filename_component(shader ${shader_path} NAME)
    string(MAKE_C_IDENTIFIER ${shader} symbol)
    set(header ${generated}/${rel_dir}/${shader}.hpp)
    add_custom_command(OUTPUT ${header}
      COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/cmake/embed_shader.py
        ${PROJECT_SOURCE_DIR} ${shader_path} ${header} ${symbol} ${header}.d
      DEPENDS ${shader_path} ${PROJECT_SOURCE_DIR}/cmake/embed_shader.py
      DEPFILE ${header}.d
      COMMENT "Embedding ${rel_dir}/${shader}")
    list(APPEND headers ${header})
  endforeach()
  target_sources(${target} PRIVATE ${headers})
  target_include_directories(${target} PRIVATE ${generated})
endfunction()
