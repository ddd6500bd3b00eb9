#pragma once
// What gpu::Program reads from a shader's text before and after the driver sees it, with no GL:
// the files an embedded shader was assembled from (cmake/embed_shader.py writes them on its first
// line, `//! files: a b ...`, and numbers them in `#line N S` directives), a driver's log with
// those numbers replaced by the file names, and the uniforms the text declares (so a name the C++
// side asks for and the shader does not declare fails loudly). docs/gpu.md "Shaders and their
// contracts".
#include <string>
#include <string_view>
#include <vector>

namespace lfd::gpu {

// The files of an embedded shader, by source-string number; empty for text that was not embedded.
std::vector<std::string> shader_files(std::string_view source);

// `log` with each "S:L(C)" (Mesa) or "S(L)" (NVIDIA) location whose source-string number S names
// one of `files` written "FILE:L"; other text unchanged.
std::string name_files_in_log(const std::string& log, const std::vector<std::string>& files);

// The names of the uniforms `source` declares outside uniform blocks (`uniform TYPE NAME...;`,
// arrays too), after removing comments. Preprocessor conditionals are not evaluated: a uniform
// declared in any branch counts as declared.
std::vector<std::string> declared_uniforms(std::string_view source);

// The first lines of every stage (before the variant's defines): "#version 450 core" for desktop
// OpenGL, or for OpenGL ES "#version 310 es", `precise` (GL_EXT_gpu_shader5 where the driver has
// it, else nothing: ES 3.1 has no such qualifier) and highp for every type ES gives a lower or no
// default precision (docs/gpu.md "OpenGL ES 3.1").
std::string glsl_version_header(bool es);

// `source` (one pass's embedded text, written once for GLSL 4.50) as GLSL ES 3.10 takes it; the
// two other differences the passes meet, rewritten in place so line numbers stay:
// - a contract's constant (`LFD_IO_INT(name, value)`, `LFD_IO_UINT`; gpu/gl/shaders/shader_io.h)
//   becomes `#define name value`: ES allows only literals in layout(binding = ...) and
//   local_size_x, where GLSL 4.40 takes constant expressions;
// - `const` on a declaration inside a function body goes: ES wants a constant expression after a
//   const (GLSL 4.20 allows any), and the passes mark their locals const. Global constants stay.
std::string glsl_es_source(std::string_view source);

}  // namespace lfd::gpu
