// lfd.Window: the display's window driven from a script (python/script_window.hpp); every call
// returns without waiting for a frame except wait() and screenshot(), which release the GIL.
#include <pybind11/stl.h>

#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/display_binding.hpp"
#include "python/scene_binding.hpp"
#include "python/script_window.hpp"

namespace py = pybind11;

namespace lfd::python {

void bind_window(py::module_& m) {
  py::class_<ScriptWindow>(m, "Window")
      .def(py::init([](const PyDisplay& display, bool simulated, const std::string& blend, bool overscan) {
             ScriptWindowOptions options{display.calibration, display.name, simulated, {}};
             options.interlace.blend = interlace::parse_view_blend(blend);
             options.interlace.overscan = overscan;
             py::gil_scoped_release release;
             return std::make_unique<ScriptWindow>(std::move(options));
           }),
           py::arg("display"), py::arg("simulated") = false, py::arg("blend") = "nearest", py::arg("overscan") = false)
      .def("_show_quilt", [](ScriptWindow& w, const PyQuilt& quilt) { w.show(quilt); }, py::arg("quilt"))
      .def(
          "_render",
          [](ScriptWindow& w, const PyScene& scene, const PyDisplay& display, const py::dict& settings,
             const std::string& backend) {
            RenderCall call{scene.scene, scene.name, display.calibration, settings_of(settings), backend};
            lightfield::check_render_settings(call.settings, lightfield::SettingNames::kKeywords);
            w.render(std::move(call));
          },
          py::arg("scene"), py::arg("display"), py::arg("settings"), py::arg("backend"))
      .def("wait", &ScriptWindow::wait, py::call_guard<py::gil_scoped_release>(),
           "Until what was handed over is on screen (and a scene rendered).")
      .def("screenshot", [](ScriptWindow& w) {
        Image8 frame;
        {
          py::gil_scoped_release release;
          frame = w.screenshot();
        }
        return image_array(std::move(frame));
      }, "The next frame as shown: the framebuffer full screen on the display, else the panel (H x W x 3 uint8).")
      .def_property_readonly("on_display", &ScriptWindow::on_display, "full screen on the display's own monitor")
      .def_property_readonly("is_open", &ScriptWindow::is_open)
      .def("close", &ScriptWindow::close, py::call_guard<py::gil_scoped_release>());
}

}  // namespace lfd::python
