// The headless context and the GL object wrappers on a real EGL context (llvmpipe here).
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {
namespace {

TEST(GlContext, HeadlessContextIsCore45WithCompute) {
  HeadlessContext context;
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  EXPECT_GE(major * 10 + minor, 45) << context.info().summary();
  EXPECT_FALSE(context.info().renderer.empty());
  EXPECT_GT(context.info().max_ssbo_bytes, 0);
}

TEST(GlContext, ComputeShaderWritesABufferThatReadsBack) {
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { uint values[]; };
uniform uint count;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < count) values[i] = i * i + SHIFT;
})";
  Program program("square", {{GL_COMPUTE_SHADER, source}}, {"SHIFT 7u"});
  const size_t n = 1000;
  Buffer buffer(n * 4);
  buffer.bind_storage(0);
  program.use();
  glUniform1ui(program.uniform("count"), GLuint(n));
  program.dispatch_1d(n, 64);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto values = buffer.download_as<uint32_t>(n);
  for (size_t i = 0; i < n; ++i) ASSERT_EQ(values[i], i * i + 7) << i;
  check_gl("compute test");
}

TEST(GlContext, ShaderCompileErrorNamesTheShader) {
  HeadlessContext context;
  try {
    Program program("broken-one", {{GL_COMPUTE_SHADER, "layout(local_size_x = 1) in; void main() { x = 1; }"}});
    FAIL() << "a broken shader compiled";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("broken-one"), std::string::npos) << e.what();
  }
}

TEST(GlContext, TexturesAndBuffersAreCountedInTheMemoryFigures) {
  HeadlessContext context;
  const size_t before = gpu_bytes_allocated();
  {
    Texture planes(GL_RGBA8, 64, 32, 5);
    Buffer b(1000);
    EXPECT_EQ(gpu_bytes_allocated() - before, 64u * 32 * 5 * 4 + 1000);
    EXPECT_GE(gpu_bytes_peak(), gpu_bytes_allocated());
  }
  EXPECT_EQ(gpu_bytes_allocated(), before);
}

}  // namespace
}  // namespace lfd::gpu
