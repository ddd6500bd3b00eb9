// The checks that keep a pass's C++ and GLSL sides agreeing (docs/gpu.md "Shaders and their
// contracts"): embedded shaders' files in compile errors, unknown and unused uniforms, shared
// binding points, the GL debug output, and no binding number or work-group size written in a
// shader outside its contract header.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/shader_source.hpp"

namespace lfd::gpu {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Strict checks for one test, whatever the environment (CTest turns them on for all).
class StrictChecks {
 public:
  StrictChecks() {
    const char* v = std::getenv("LFD_GL_CHECKS");
    if (v) old_ = v;
    setenv("LFD_GL_CHECKS", "strict", 1);
  }
  ~StrictChecks() { old_.empty() ? unsetenv("LFD_GL_CHECKS") : setenv("LFD_GL_CHECKS", old_.c_str(), 1); }

 private:
  std::string old_;
};

TEST(ShaderSource, FilesComeFromTheEmbeddedFirstLine) {
  EXPECT_THAT(shader_files("//! files: gpu/shaders/a.comp.glsl gpu/shaders/b.glsl\n#line 1 0\n"),
              ::testing::ElementsAre("gpu/shaders/a.comp.glsl", "gpu/shaders/b.glsl"));
  EXPECT_TRUE(shader_files("void main() {}\n").empty());
}

TEST(ShaderSource, LogLocationsNameTheFile) {
  const std::vector<std::string> files{"gpu/shaders/a.comp.glsl", "gpu/shaders/b.glsl"};
  // Mesa's form, then NVIDIA's.
  EXPECT_EQ(name_files_in_log("1:12(5): error: `x' undeclared\n0:3(1): error: y\n", files),
            "gpu/shaders/b.glsl:12(5): error: `x' undeclared\ngpu/shaders/a.comp.glsl:3(1): error: y\n");
  EXPECT_EQ(name_files_in_log("1(7) : error C1008: undefined variable \"x\"\n", files),
            "gpu/shaders/b.glsl:7 : error C1008: undefined variable \"x\"\n");
  // A number that names no file, and a log of text that was not embedded, stay as they are.
  EXPECT_EQ(name_files_in_log("4:2(1): error: z\n", files), "4:2(1): error: z\n");
  EXPECT_EQ(name_files_in_log("0:2(1): error: z\n", {}), "0:2(1): error: z\n");
}

TEST(ShaderSource, DeclaredUniformsSkipBlocksAndComments) {
  const char* source = R"(
uniform uint count;               // a scalar
uniform highp vec2 offsets[4], scale;
layout(binding = 0) uniform sampler2D planes;
uniform Params { float hidden; };  // a block: its members have no locations
// uniform float commented;
/* uniform float also_commented; */
uniform mat4 view = mat4(1.0);
)";
  EXPECT_THAT(declared_uniforms(source), ::testing::ElementsAre("count", "offsets", "scale", "planes", "view"));
}

TEST(GlProgram, CompileErrorsNameTheIncludedFileAndLine) {
  HeadlessContext context;
  const char* embedded =
      "//! files: gpu/shaders/main.comp.glsl gpu/shaders/piece.glsl\n"
      "#line 1 0\nlayout(local_size_x = 1) in;\n"
      "#line 1 1\nfloat piece() { return 1.0; }\nfloat broken() { return undeclared_name; }\n"
      "#line 3 0\nvoid main() {}\n";
  try {
    Program("contract test", {{GL_COMPUTE_SHADER, embedded}});
    FAIL() << "compiled";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("gpu/shaders/piece.glsl:2")) << e.what();
    EXPECT_THAT(e.what(), HasSubstr("contract test")) << e.what();
  }
}

TEST(GlProgram, AUniformTheSourcesDoNotDeclareThrowsNamingIt) {
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { uint value; };
uniform uint count;
void main() { value = count; })";
  const Program program("uniform test", {{GL_COMPUTE_SHADER, source}});
  EXPECT_GE(program.uniform("count"), 0);
  try {
    program.uniform("cuont");
    FAIL() << "a misspelt uniform was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'cuont'"));
    EXPECT_THAT(e.what(), HasSubstr("uniform test"));
  }
}

TEST(GlProgram, AnUnusedUniformThrowsUnderStrictChecks) {
  StrictChecks strict;
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { uint value; };
uniform uint count;
uniform uint forgotten;  // declared, never read: the compiler drops it
void main() { value = count; })";
  const Program program("unused test", {{GL_COMPUTE_SHADER, source}});
  try {
    program.uniform("forgotten");
    FAIL() << "an unused uniform was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'forgotten' is declared but unused"));
  }
}

TEST(GlProgram, TwoBlocksOnOneBindingThrowNamingBoth) {
  HeadlessContext context;
  const char* source = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 3) readonly buffer Keys { uint keys[]; };
layout(std430, binding = 3) writeonly buffer Counts { uint counts[]; };
void main() { counts[0] = keys[0]; })";
  try {
    Program("binding test", {{GL_COMPUTE_SHADER, source}});
    FAIL() << "two blocks on one binding were accepted";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("Keys"));
    EXPECT_THAT(e.what(), HasSubstr("Counts"));
    EXPECT_THAT(e.what(), HasSubstr("binding 3"));
  }
}

TEST(GlDebug, TheDriversErrorMessageReachesCheckGl) {
  StrictChecks strict;
  HeadlessContext context;
  glBindBufferBase(GL_ARRAY_BUFFER, 0, 0);  // not an indexed target: GL_INVALID_ENUM
  try {
    check_gl("binding a buffer to an unindexed target");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("after binding a buffer to an unindexed target"));
    EXPECT_THAT(e.what(), HasSubstr("glBindBufferBase")) << "the driver's own message: " << e.what();
  }
  EXPECT_EQ(take_gl_debug_error(), "");
  check_gl("after the error was reported");
}

// Every shader file of every module: binding points and work-group sizes come from the pass
// family's contract header (gpu/*/shaders/*_io.h), read by C++ too, never a number in the shader.
TEST(ShaderContract, NoShaderWritesABindingNumberOrAWorkGroupSize) {
  const std::regex literal(R"((\bbinding\s*=\s*[0-9])|(\blocal_size_[xyz]\s*=\s*[0-9]))");
  std::vector<std::string> found;
  const std::filesystem::path source(LFD_SOURCE_DIR);
  for (auto it = std::filesystem::recursive_directory_iterator(source); it != decltype(it)(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.starts_with("build") || name.starts_with(".") || name == "node_modules" ||
                               name == "tests")) {
      it.disable_recursion_pending();  // build trees, git, npm clients: not the project's shaders
      continue;
    }
    if (it->path().extension() != ".glsl" || it->path().parent_path().filename() != "shaders") continue;
    std::ifstream in(it->path());
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      const std::string code = line.substr(0, line.find("//"));
      if (std::regex_search(code, literal))
        found.push_back(std::filesystem::relative(it->path(), source).string() + ":" + std::to_string(number) + ": " +
                        line);
    }
  }
  EXPECT_TRUE(found.empty()) << "numbers that belong in the contract header:\n"
                             << ::testing::PrintToString(found);
}

}  // namespace
}  // namespace lfd::gpu
