// The shader assembly for OpenGL ES 3.1 (gpu/gl/shader_source.hpp, docs/gpu.md "OpenGL ES 3.1"):
// one source per pass, what GLSL ES 3.10 wants different rewritten in place, line for line.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "gpu/gl/shader_source.hpp"

namespace lfd::gpu {
namespace {

size_t lines(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

TEST(GlslEsSource, ContractConstantsBecomeMacros) {
  const std::string in =
      "LFD_IO_INT(kQuiltUnit, 0)      // texture unit\n"
      "LFD_IO_UINT(kGroupWidth, 16u)\n"
      "LFD_IO_INT(kEntries, kA * kB * 3)\n"
      "layout(binding = kQuiltUnit) uniform sampler2D quilt;\n";
  const std::string out = glsl_es_source(in);
  EXPECT_NE(out.find("#define kQuiltUnit 0      // texture unit\n"), std::string::npos) << out;
  EXPECT_NE(out.find("#define kGroupWidth 16u\n"), std::string::npos) << out;
  EXPECT_NE(out.find("#define kEntries (kA * kB * 3)\n"), std::string::npos) << out;
  EXPECT_NE(out.find("layout(binding = kQuiltUnit) uniform sampler2D quilt;"), std::string::npos) << out;
  EXPECT_EQ(lines(out), lines(in));
}

TEST(GlslEsSource, LocalConstGoesGlobalConstStays) {
  const std::string in =
      "const float kFar = 2.0 / 3.0;\n"
      "float f(const in float x) {\n"
      "  const vec2 uv = vec2(x, 1.0 - x);  // const here: a comment\n"
      "  precise const float a = uv.x;\n"
      "  /* const */ float constant_b = a;\n"
      "  return a + constant_b;\n"
      "}\n";
  const std::string out = glsl_es_source(in);
  EXPECT_NE(out.find("const float kFar = 2.0 / 3.0;"), std::string::npos) << out;
  EXPECT_NE(out.find("float f(const in float x)"), std::string::npos) << out;
  EXPECT_NE(out.find("  vec2 uv = vec2(x, 1.0 - x);  // const here: a comment"), std::string::npos) << out;
  EXPECT_NE(out.find("  precise float a = uv.x;"), std::string::npos) << out;
  EXPECT_NE(out.find("/* const */ float constant_b = a;"), std::string::npos) << out;
  EXPECT_EQ(lines(out), lines(in));
}

// An embedded pass as cmake/embed_shader.py writes it: the files list, #line per file, the
// contract pasted in.
TEST(GlslEsSource, AnEmbeddedPassKeepsItsLinesAndFiles) {
  const std::string in =
      "//! files: gpu/panel/shaders/interlace.comp.glsl gpu/panel/shaders/lens_view_io.h\n"
      "#line 1 0\n"
      "#line 1 1\n"
      "#ifndef LFD_GPU_SHADERS_LENS_VIEW_IO_H\n"
      "LFD_IO_UINT(kInterlaceGroupWidth, 16u)\n"
      "#endif\n"
      "#line 3 0\n"
      "layout(local_size_x = kInterlaceGroupWidth) in;\n"
      "void main() {\n"
      "  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);\n"
      "}\n";
  const std::string out = glsl_es_source(in);
  EXPECT_EQ(lines(out), lines(in));
  EXPECT_EQ(shader_files(out), shader_files(in));
  EXPECT_EQ(out.find("LFD_IO_INT("), std::string::npos);
  EXPECT_NE(out.find("#define kInterlaceGroupWidth 16u"), std::string::npos);
  EXPECT_NE(out.find("  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);"), std::string::npos) << out;
}

TEST(GlslEsSource, VersionHeaders) {
  EXPECT_EQ(glsl_version_header(false), "#version 450 core\n");
  const std::string es = glsl_version_header(true);
  EXPECT_EQ(es.rfind("#version 310 es\n", 0), 0u);
  for (const char* needed : {"precision highp float;", "precision highp int;", "precision highp sampler2D;",
                             "precision highp image2D;", "#define precise"})
    EXPECT_NE(es.find(needed), std::string::npos) << needed;
}

}  // namespace
}  // namespace lfd::gpu
