#pragma once
// The GL debug output under strict checks (LFD_GL_CHECKS=strict: every test). A context made by
// gpu/ asks for debug output then, and the callback keeps the first error the driver reports;
// check_gl (gpu/gl/gl_name.hpp) throws with it, so a misused call fails the test that made it,
// naming the driver's message, even where no glGetError is read. docs/gpu.md "Shaders and their
// contracts".
#include <string>

namespace lfd::gpu {

// Installs the callback on the current context when strict checks are on; nothing otherwise.
void enable_gl_debug_output();

// The first error message the callback received since the last call, then cleared ("" if none).
std::string take_gl_debug_error();

}  // namespace lfd::gpu
