// Passes declare their bindings (docs/gpu.md "Binding points"): a declaration that disagrees with
// the shader throws at link time, and under strict checks a dispatch or draw whose declared
// points do not hold what the pass bound throws, naming the pass and the point.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {
namespace {

using ::testing::HasSubstr;

// LFD_GL_CHECKS set to `value` (or unset) for one test, whatever the environment.
class GlChecks {
 public:
  explicit GlChecks(const char* value) {
    const char* v = std::getenv("LFD_GL_CHECKS");
    if (v) old_ = v;
    value ? setenv("LFD_GL_CHECKS", value, 1) : unsetenv("LFD_GL_CHECKS");
  }
  ~GlChecks() { old_.empty() ? unsetenv("LFD_GL_CHECKS") : setenv("LFD_GL_CHECKS", old_.c_str(), 1); }

 private:
  std::string old_;
};

// Point 11 as in the frame contract, shared by several passes; the sum of `values` into `range`.
constexpr const char* kSumSource = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 5) readonly buffer Values { uint values[]; };
layout(std430, binding = 11) buffer Range { uint range[]; };
void main() { range[0] = values[0] + values[1]; })";

Program sum_program(int range_point = 11) {
  return Program("sum", {{GL_COMPUTE_SHADER, kSumSource}}, {},
                 {storage_buffer("values", 5, Access::read), storage_buffer("depth_range", range_point, Access::write)});
}

TEST(GlBindings, ADispatchBoundAsDeclaredRuns) {
  GlChecks strict("strict");
  HeadlessContext context;
  const Program program = sum_program();
  const uint32_t values[2] = {3, 4};
  Buffer in(sizeof values, values), out(sizeof(uint32_t));
  program.use();
  program.bind("values", in);
  program.bind("depth_range", out);
  program.dispatch(1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  EXPECT_EQ(out.download_as<uint32_t>(1)[0], 7u);
}

TEST(GlBindings, AWrongBufferAtADeclaredPointThrowsNamingThePassAndThePoint) {
  GlChecks strict("strict");
  HeadlessContext context;
  const Program program = sum_program();
  const uint32_t values[2] = {3, 4};
  Buffer in(sizeof values, values), out(sizeof(uint32_t)), other(sizeof(uint32_t));
  program.use();
  program.bind("values", in);
  program.bind("depth_range", out);
  other.bind_storage(11);  // a helper that rebinds the shared point between the bind and the dispatch
  try {
    program.dispatch(1);
    FAIL() << "a dispatch read a buffer its pass did not bind";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("pass 'sum'"));
    EXPECT_THAT(e.what(), HasSubstr("point 11 (storage buffer 'depth_range')"));
    EXPECT_THAT(e.what(), HasSubstr("holds buffer " + std::to_string(other.id())));
  }
}

// The spread dispatch (gpu/gl/gl_work_groups.hpp) checks like the others: no pass can skip it.
TEST(GlBindings, TheSpreadDispatchChecksTheBindingsToo) {
  GlChecks strict("strict");
  HeadlessContext context;
  const Program program = sum_program();
  const uint32_t values[2] = {3, 4};
  Buffer in(sizeof values, values), out(sizeof(uint32_t)), other(sizeof(uint32_t));
  program.use();
  program.bind("values", in);
  program.bind("depth_range", out);
  program.dispatch_groups(1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  EXPECT_EQ(out.download_as<uint32_t>(1)[0], 7u);
  other.bind_storage(11);
  EXPECT_THROW(program.dispatch_groups(1), std::logic_error);
  EXPECT_TRUE(program.declares("depth_range"));
  EXPECT_FALSE(program.declares("range"));
}

TEST(GlBindings, ADeclaredPointNeverBoundThrowsNamingThePassAndThePoint) {
  GlChecks strict("strict");
  HeadlessContext context;
  const Program program = sum_program();
  Buffer out(sizeof(uint32_t));
  program.use();
  program.bind("depth_range", out);
  try {
    program.dispatch_1d(1, 1);
    FAIL() << "a dispatch ran with a declared point never bound";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("pass 'sum'"));
    EXPECT_THAT(e.what(), HasSubstr("point 5 (storage buffer 'values') was never bound"));
  }
}

TEST(GlBindings, ADeclarationThatDisagreesWithTheShaderThrowsAtLinkTime) {
  HeadlessContext context;
  try {
    sum_program(12);  // the shader's Range is at 11
    FAIL() << "a declaration of point 12 linked against a shader using 11";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("program 'sum'"));
    EXPECT_THAT(e.what(), HasSubstr("point 11 (storage buffer 'Range' in the shader) is not declared"));
  }
  // A declared point the shader does not use.
  try {
    Program("sum", {{GL_COMPUTE_SHADER, kSumSource}}, {},
            {storage_buffer("values", 5, Access::read), storage_buffer("depth_range", 11, Access::write),
             image("target", 0, Access::write)});
    FAIL() << "a declared image the shader does not have was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("program 'sum'"));
    EXPECT_THAT(e.what(), HasSubstr("point 0 (image 'target') is declared but the shader uses no image there"));
  }
}

TEST(GlBindings, ImagesAndTexturesAreCheckedTooAndNamesMustBeDeclared) {
  GlChecks strict("strict");
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 1) in;
layout(binding = 2) uniform sampler2DArray planes;
layout(binding = 1, rgba32f) writeonly uniform image2D target;
void main() { imageStore(target, ivec2(0), texelFetch(planes, ivec3(0), 0)); })";
  const Program program("copy", {{GL_COMPUTE_SHADER, source}}, {},
                        {texture("planes", 2), image("target", 1, Access::write)});
  const Texture planes(GL_RGBA32F, 1, 1, 2), target(GL_RGBA32F, 1, 1), other(GL_RGBA32F, 1, 1);
  program.use();
  program.bind("planes", planes);
  program.bind("target", target);
  program.dispatch(1);
  glBindTextureUnit(2, 0);  // an unbind by someone else
  try {
    program.dispatch(1);
    FAIL() << "a dispatch sampled a texture unit its pass did not bind";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("pass 'copy': point 2 (texture 'planes') holds texture 0"));
  }
  program.bind("planes", planes);
  glBindImageTexture(1, other.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  EXPECT_THROW(program.dispatch(1), std::logic_error);
  try {
    program.bind("plane", planes);
    FAIL() << "a misspelt binding was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("pass 'copy': no binding 'plane' is declared"));
  }
}

TEST(GlBindings, WithoutStrictChecksNothingIsAsked) {
  GlChecks off(nullptr);
  HeadlessContext context;
  const Program program = sum_program();
  const uint32_t values[2] = {3, 4};
  Buffer in(sizeof values, values), out(sizeof(uint32_t)), other(sizeof(uint32_t));
  program.use();
  program.bind("values", in);
  program.bind("depth_range", out);
  other.bind_storage(11);
  EXPECT_NO_THROW(program.dispatch(1));  // the check is the tests' (and a developer's), not a frame's
}

}  // namespace
}  // namespace lfd::gpu
