// The bridge that lets one declaration be C++ and GLSL (docs/gpu.md "Shaders and their
// contracts"). A pass family's contract header (gpu/*/shaders/*_io.h) is #included by its C++
// callers and by its shaders (cmake/embed_shader.py pastes it in, once per shader), so a binding
// point, a work-group size, a limit or a buffer's struct layout is written once and the two
// sides cannot drift apart (a `binding = 7` in GLSL beside a `bind_storage(7)` in C++ did).
//
// Both languages understand the preprocessor lines, `struct { ... };` of scalar members and
// `LFD_IO_*` as macros; only the spelling of a constant differs, so that is all this file maps:
// - LFD_IO_INT(name, value): binding points and unit numbers (GL takes them as GLuint; C++
//   converts; GLSL 4.40 allows a constant expression in layout(binding = ...) and local_size_x,
//   and every GL test compiles the shaders that way on Mesa).
// - LFD_IO_UINT(name, value): sizes and limits the shader computes with in uint (write the value
//   with a `u`, valid in both languages).
// - LFD_IO_ZERO after a struct member: zero-initialised in C++ (a default member initializer,
//   which GLSL has no syntax for), nothing in GLSL.
// - LFD_IO_BEGIN(module) ... LFD_IO_END: the names are in namespace lfd::module in C++ (the
//   module that owns the shaders), where `uint` is std::uint32_t and `vec4`, `ivec4`, `uvec4` are
//   glm's (16 bytes, 4-byte aligned: a struct of them has its std430 layout), so struct members
//   read the same as in GLSL; GLSL has no namespaces.
// On OpenGL ES (docs/gpu.md "OpenGL ES 3.1") the shader assembly turns each LFD_IO_INT and
// LFD_IO_UINT line into `#define name value` (GLSL ES 3.10 takes only literals in layout
// qualifiers): write one per line, at the start of the line (gpu::glsl_es_source).
// Include guards, not #pragma once: GLSL would warn about an unknown pragma (the embedder
// pastes each file once anyway).
#ifndef LFD_GPU_SHADERS_SHADER_IO_H
#define LFD_GPU_SHADERS_SHADER_IO_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/vec4.hpp>
#define LFD_IO_BEGIN(module)  \
  namespace lfd::module {    \
  using uint = std::uint32_t; \
  using vec4 = glm::vec4;     \
  using ivec4 = glm::ivec4;   \
  using uvec4 = glm::uvec4;
#define LFD_IO_END }
#define LFD_IO_INT(name, value) inline constexpr int name = value;
#define LFD_IO_UINT(name, value) inline constexpr std::uint32_t name = value;
#define LFD_IO_ZERO {}
#else
#define LFD_IO_BEGIN(module)
#define LFD_IO_END
#define LFD_IO_INT(name, value) const int name = value;
#define LFD_IO_UINT(name, value) const uint name = value;
#define LFD_IO_ZERO
#endif

#endif
