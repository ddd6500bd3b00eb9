// Reproducer of a Mesa 22.3 zink bug (docs/gpu.md "What zink found"): after glFlush, glFinish
// returns before the flushed work is done (and a fence made then signals at once), so a fence
// behind that work still polls unsignalled after glFinish. The GL 4.5 core specification: Finish
// returns only when every earlier command is complete, fence commands included. Standalone: EGL
// surfaceless, OpenGL 4.5 core, libepoxy; nothing of lfd.
//
//   cc zink_finish_after_flush.c $(pkg-config --cflags --libs epoxy) -o zink_finish_after_flush
//   export EGL_PLATFORM=surfaceless LIBGL_ALWAYS_SOFTWARE=1 MESA_LOADER_DRIVER_OVERRIDE=zink
//   XDG_RUNTIME_DIR=/tmp ./zink_finish_after_flush         -> exit 1 (llvmpipe: exit 0)
//   XDG_RUNTIME_DIR=/tmp ./zink_finish_after_flush fence   -> exit 0: waiting on the work's own
//                                                             fence works (what lfd's tests do)
//
// A compute dispatch long enough to be running still, its fence, glFlush, then glFinish (or, with
// the argument `fence`, glClientWaitSync on the dispatch's own fence); then the fence is polled.
// Exit 0: the fence had signalled; 1: it had not; 2: no GL 4.5 context.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <stdio.h>
#include <string.h>

static const char* kSource =
    "#version 450\n"
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) writeonly buffer Out { uint values[]; };\n"
    "void main() {\n"
    "  uint x = gl_GlobalInvocationID.x;\n"
    "  for (uint i = 0u; i < 20000u; ++i) x = x * 1664525u + 1013904223u;\n"
    "  values[gl_GlobalInvocationID.x] = x;\n"
    "}\n";

static int make_context(void) {
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (!eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) return 0;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  return context != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

int main(int argc, char** argv) {
  const int wait_on_fence = argc > 1 && strcmp(argv[1], "fence") == 0;
  if (!make_context()) {
    fprintf(stderr, "no OpenGL 4.5 core context on EGL surfaceless\n");
    return 2;
  }
  printf("%s\n", (const char*)glGetString(GL_RENDERER));
  GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &kSource, NULL);
  glCompileShader(shader);
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glUseProgram(program);
  GLuint out = 0;
  glCreateBuffers(1, &out);
  glNamedBufferStorage(out, 4 * 64 * 1024, NULL, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out);
  glDispatchCompute(1, 1, 1);  // the pipeline built before the measured dispatch
  glFinish();

  glDispatchCompute(1024, 1, 1);
  GLsync done = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();
  if (wait_on_fence)
    glClientWaitSync(done, GL_SYNC_FLUSH_COMMANDS_BIT, ~(GLuint64)0);
  else
    glFinish();
  const GLenum status = glClientWaitSync(done, 0, 0);  // a poll
  const int signalled = status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
  printf("after glFlush and %s: the dispatch's fence %s\n", wait_on_fence ? "waiting on that fence" : "glFinish",
         signalled ? "has signalled" : "has NOT signalled");
  glClientWaitSync(done, GL_SYNC_FLUSH_COMMANDS_BIT, ~(GLuint64)0);  // leave nothing running
  glDeleteSync(done);
  return signalled ? 0 : 1;
}
