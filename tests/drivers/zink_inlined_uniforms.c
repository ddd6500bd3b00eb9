// Reproducer of a Mesa 22.3 zink bug (docs/gpu.md "What zink found"): with uniform inlining on
// (ZINK_INLINE_UNIFORMS; zink's default on CPU Vulkan devices such as lavapipe), a compute
// program can run with the shader variant compiled for an earlier value of a uniform that decides
// a branch, after the program was switched away from and back. Standalone: EGL surfaceless,
// OpenGL 4.5 core, libepoxy; nothing of lfd.
//
//   cc zink_inlined_uniforms.c $(pkg-config --cflags --libs epoxy) -o zink_inlined_uniforms
//   export EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 MESA_LOADER_DRIVER_OVERRIDE=zink
//   XDG_RUNTIME_DIR=/tmp ./zink_inlined_uniforms                          -> exit 1, one wrong
//   XDG_RUNTIME_DIR=/tmp ZINK_INLINE_UNIFORMS=0 ./zink_inlined_uniforms   -> exit 0 (so llvmpipe)
//
// Two compute programs (they must differ, or Mesa makes them one) count to a length taken from
// a buffer (0) or from a uniform (1), as `from_buffer` says; `other` adds 1000. Six dispatches
// with the uniforms set before each; the sixth reads the buffer though from_buffer is false.
// Exit 0: every result right; 1: a result wrong (printed); 2: no GL 4.5 context.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <stdio.h>

static const char* kSource =
    "#version 450\n"
    "layout(local_size_x = 1) in;\n"
    "layout(std430, binding = 0) buffer Data { uint length_in_buffer; uint result[2]; };\n"
    "uniform bool from_buffer;\n"
    "uniform uint length;\n"
    "uniform bool other;\n"
    "void main() {\n"
    "  uint n = from_buffer ? length_in_buffer : length;\n"
    "  uint r = 0u;\n"
    "  for (uint i = 0u; i < n; ++i) r += 1u;\n"
    "  if (other) r += 1000u;\n"
    "  result[%u] = r;\n"
    "}\n";

static GLuint program_writing_slot(unsigned slot) {
  char text[1024];
  snprintf(text, sizeof text, kSource, slot);
  const char* source = text;
  GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &source, NULL);
  glCompileShader(shader);
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  return linked ? program : 0;
}

static int make_context(void) {
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (!eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) return 0;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

int main(void) {
  if (!make_context()) {
    fprintf(stderr, "no OpenGL 4.5 core context on EGL surfaceless\n");
    return 2;
  }
  printf("%s\n", (const char*)glGetString(GL_RENDERER));
  const GLuint programs[2] = {program_writing_slot(0), program_writing_slot(1)};
  if (!programs[0] || !programs[1]) {
    fprintf(stderr, "the compute programs did not link\n");
    return 2;
  }
  const unsigned zeros[3] = {0, 0, 0};  // length_in_buffer = 0
  GLuint data = 0;
  glCreateBuffers(1, &data);
  glNamedBufferStorage(data, sizeof zeros, zeros, 0);
  // {program, from_buffer, other}: the shortest sequence found that goes wrong (at the last).
  const int steps[6][3] = {{1, 1, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 1}, {0, 0, 1}, {1, 0, 1}};
  int wrong = 0;
  for (int s = 0; s < 6; ++s) {
    const GLuint p = programs[steps[s][0]];
    glProgramUniform1i(p, glGetUniformLocation(p, "from_buffer"), steps[s][1]);
    glProgramUniform1ui(p, glGetUniformLocation(p, "length"), 1);
    glProgramUniform1i(p, glGetUniformLocation(p, "other"), steps[s][2]);
    glUseProgram(p);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, data);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    unsigned got[3];
    glGetNamedBufferSubData(data, 0, sizeof got, got);
    const unsigned want = (steps[s][1] ? 0u : 1u) + (steps[s][2] ? 1000u : 0u);
    const unsigned result = got[1 + steps[s][0]];
    printf("dispatch %d: program %d, from_buffer %d, other %d: %u%s\n", s + 1, steps[s][0], steps[s][1],
           steps[s][2], result, result == want ? "" : " WRONG");
    if (result != want) ++wrong;
  }
  return wrong ? 1 : 0;
}
