#pragma once
// One render as Python asks for it, with no Python in it (it runs with the GIL released, and on
// the display window's render thread): the scene, the display, `lfd render`'s settings
// (lightfield/render_settings.hpp) and the backend; the GL backend renders on a headless context
// kept per thread.
#include <memory>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "lightfield/render_settings.hpp"
#include "python/quilt_binding.hpp"
#include "scene/scene.hpp"
#include "util/image.hpp"

namespace lfd::python {

struct RenderCall {
  std::shared_ptr<const scene::Scene> scene;
  std::string scene_name;
  std::optional<display::Calibration> display;
  lightfield::RenderSettings settings;
  std::string backend = "cpu";  // cpu | gl | auto
};

// The quilt `lfd render` writes for the same settings (8 bits, as the file holds it).
PyQuilt render_quilt(const RenderCall& call);
// One view (0 = leftmost), as `lfd render --view`.
Image8 render_view(const RenderCall& call, int view);

// Makes this thread's headless GL context current (made on first use): the GL interlacer's.
void use_gl_context();

// Lets go of the headless GL contexts kept per thread (at interpreter exit).
void release_gl_devices();

}  // namespace lfd::python
