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

}  // namespace lfd::gpu
