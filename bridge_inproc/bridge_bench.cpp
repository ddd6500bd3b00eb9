#include "bridge_inproc/bridge_bench.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <vector>

#include <epoxy/gl.h>

#include "bridge_inproc/bridge_settings.hpp"
#include "gpu/gl/gl_context.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::bridge {

namespace {

// The few functions the benchmark calls, looked up as a client does.
struct Library {
  void* handle = nullptr;
  bool (*initialize)(const char*) = nullptr;
  bool (*uninitialize)() = nullptr;
  bool (*window_gl)(unsigned long*, unsigned long) = nullptr;
  bool (*offscreen_gl)(unsigned long*, unsigned long) = nullptr;
  bool (*draw)(unsigned long, unsigned long long, unsigned, unsigned long, unsigned long, unsigned long,
               unsigned long, float, float) = nullptr;
  bool (*offscreen_texture)(unsigned long, unsigned long long*, unsigned*, unsigned long*, unsigned long*) = nullptr;

  template <typename F>
  void bind(F& f, const char* name) {
    f = reinterpret_cast<F>(dlsym(handle, name));
    if (!f) throw_input_error("{}: no function {}", "libbridge_inproc", name);
  }
  explicit Library(const std::filesystem::path& path) {
    handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw_input_error("{}: cannot load ({})", path.string(), dlerror());
    bind(initialize, "initialize_bridge");
    bind(uninitialize, "uninitialize_bridge");
    bind(window_gl, "instance_window_gl");
    bind(offscreen_gl, "instance_offscreen_window_gl");
    bind(draw, "draw_interop_quilt_texture_gl");
    bind(offscreen_texture, "get_offscreen_window_texture_gl");
  }
  ~Library() { dlclose(handle); }
};

GLuint make_quilt_texture(int size) {
  std::vector<uint8_t> pixels(size_t(size) * size * 4);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t((i * 2654435761u) >> 24);
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_RGBA8, size, size);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t, 0, 0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glFinish();
  return t;
}

}  // namespace

std::vector<BridgeBenchRow> run_bridge_bench(const BridgeBenchOptions& options) {
  // The library reads its display from lfd's bridge settings: a file of the benchmark's own.
  const std::filesystem::path settings =
      std::filesystem::temp_directory_path() / ("lfd-bridge-bench-" + std::to_string(getpid()) + ".json");
  LfdBridgeSettings s;
  s.calibrations = {std::filesystem::absolute(options.calibration).string()};
  s.device = "";
  write_lfd_settings(settings, s);
  setenv("LFD_BRIDGE_CONFIG", settings.c_str(), 1);

  Library lib(options.library);
  gpu::HeadlessContext caller;  // the client's context
  caller.make_current();
  if (!lib.initialize("lfd bench bridge")) throw_input_error("initialize_bridge failed (see its log line)");
  unsigned long window = 0;
  const bool made = options.on_screen ? lib.window_gl(&window, 0) : lib.offscreen_gl(&window, 0);
  if (!made) throw_input_error("making the window failed (see the library's log line)");
  std::vector<BridgeBenchRow> rows;
  for (int size : options.quilt_sizes) {
    const GLuint texture = make_quilt_texture(size);
    BridgeBenchRow row;
    row.quilt_size = size;
    const float aspect = float(size / 8) / float(size / 6);
    for (int i = 0; i < options.warmup + options.runs; ++i) {
      Stopwatch frame;
      Stopwatch hold;
      if (!lib.draw(window, texture, 0x1908, size, size, 8, 6, aspect, 1.0f))
        throw_input_error("draw_interop_quilt_texture_gl failed (see the library's log line)");
      const double hold_s = hold.seconds();
      if (!options.on_screen) {
        // The frame is done when its panel can be read (the call waits for the drawing thread).
        unsigned long long t = 0;
        unsigned format = 0;
        unsigned long w = 0, h = 0;
        lib.offscreen_texture(window, &t, &format, &w, &h);
      }
      if (i >= options.warmup) {
        row.hold_s.push_back(hold_s);
        row.frame_s.push_back(frame.seconds());
      }
    }
    glDeleteTextures(1, &texture);
    rows.push_back(row);
  }
  lib.uninitialize();
  std::filesystem::remove(settings);
  return rows;
}

}  // namespace lfd::bridge
