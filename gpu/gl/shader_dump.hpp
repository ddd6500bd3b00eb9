#pragma once
// Every shader variant the program builds, written out for the reference GLSL front end
// (docs/gpu.md "Drivers and limits"): with LFD_SHADER_DUMP=DIR in the environment, each stage a
// Program compiles and links is written whole (the version line, the variant's defines, the
// embedded source with its `//! files:` list and #line numbers) to
// DIR/<program label>-<hash of the text>.<comp|vert|frag>, once per distinct text, so the files
// in DIR are the list of variants. The tests set it for every GL test; the CTest test
// ShaderVariants.ReferenceCompiler then compiles each with glslangValidator as GLSL 4.50
// (scripts/check-shader-variants.sh). Unset: nothing is written and nothing is read.
#include <string>
#include <string_view>

#include <epoxy/gl.h>

namespace lfd::gpu {

// Writes one stage of a program that compiled and linked (atomically: concurrent test processes
// write the same file). Throws nothing: a dump that cannot be written is reported once on stderr.
void dump_shader_variant(std::string_view label, GLenum stage, const std::string& header, const char* source);

}  // namespace lfd::gpu
