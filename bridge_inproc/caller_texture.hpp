#pragma once
// The caller's textures, on the caller's thread (docs/bridge-inproc.md "The caller's texture").
// The library draws on its own thread and GL context; a client's texture belongs to the client's
// context (a GLFW/GLX window's, an EGL context's), which shares nothing with lfd's. The one route
// that works for every kind of caller context, Mesa llvmpipe under Xvfb included, is a copy
// through memory: read the texture with glGetTexImage (desktop GL) or through a framebuffer and
// glReadPixels (OpenGL ES), on the caller's thread, while its context is current. The caller's
// bindings and pixel-store state are put back as they were; only that copy holds the caller.
#include <cstdint>
#include <vector>

namespace lfd::bridge {

// RGBA8 pixels, rows bottom-up (GL's order).
struct RgbaPixels {
  int width = 0, height = 0;
  std::vector<uint8_t> bytes;
};

// Pixel formats a caller's texture may be read as (Bridge's PixelFormats numbers): RGB, RGBA,
// BGRA, red, sRGB(A), R32F, RGBA32F, RGB10_A2. BadCall for any other (compressed, integer,
// NoFormat) naming the number.
void check_readable_format(unsigned format);

// Reads texture `name` of the context current on this thread into `storage` (a recycled buffer:
// one over glibc's 32 MiB mmap threshold would be mapped and faulted in anew for every frame).
// BadCall when no GL context is current, `name` is 0 or not a texture of that context, or its
// level 0 is not width x height.
RgbaPixels read_caller_texture(unsigned name, int width, int height, std::vector<uint8_t> storage = {});

// Puts `pixels` into texture `name` of the caller's current context, making a new RGBA8 texture
// when `name` is 0 or no longer a texture there; returns the texture. BadCall without a context.
unsigned upload_to_caller_texture(unsigned name, const RgbaPixels& pixels);

}  // namespace lfd::bridge
