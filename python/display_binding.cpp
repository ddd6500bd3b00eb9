#include "python/display_binding.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "device/device_discovery.hpp"
#include "display/display_figures.hpp"
#include "display/display_quilt.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace lfd::python {

void bind_display(py::module_& m) {
  py::class_<PyDisplay>(m, "Display", "A display: its calibration and the figures derived from it.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) { return PyDisplay{display::read_calibration(path), path.string()}; },
          py::arg("path"), "Reads visual.json or calibration.json.")
      .def_static(
          "from_device",
          [](const std::string& which, const std::string& root) {
            device::DiscoveryOptions options;
            options.root = root;
            const device::Discovery found = device::discover_devices(options);
            const device::FoundDevice& unit = device::select_device(found, which);
            return PyDisplay{device::calibration_of(unit),
                             "device " + (unit.serial.empty() ? unit.source : unit.serial)};
          },
          py::arg("which") = "auto", py::arg("root") = "/",
          "The calibration of an attached Looking Glass: 'auto' (the only one) or a serial (`lfd device list`).")
      .def_property_readonly("name", [](const PyDisplay& d) { return d.name; })
      .def_property_readonly("serial", [](const PyDisplay& d) { return d.calibration.display.serial; })
      .def_property_readonly("screen", [](const PyDisplay& d) {
        return py::make_tuple(d.calibration.display.screen_w, d.calibration.display.screen_h);
      }, "(width, height) of the panel in pixels")
      .def_property_readonly("dpi", [](const PyDisplay& d) { return d.calibration.display.dpi; })
      .def_property_readonly("pitch_lpi", [](const PyDisplay& d) { return d.calibration.display.pitch_lpi; })
      .def_property_readonly("slope", [](const PyDisplay& d) { return d.calibration.display.slope; })
      .def_property_readonly("center_periods", [](const PyDisplay& d) { return d.calibration.display.center_periods; })
      .def_property_readonly("view_cone_deg", [](const PyDisplay& d) {
        return display::effective_view_cone_deg(d.calibration);
      }, "the cone renderers use: the measured one when the calibration has it")
      .def_property_readonly("recommended_views", [](const PyDisplay& d) {
        return display::quilt_for_display(d.calibration).views;
      })
      .def_property_readonly("quilt", [](const PyDisplay& d) {
        const display::DisplayQuilt q = display::quilt_for_display(d.calibration);
        py::dict out;
        out["views"] = q.views;
        out["cols"] = q.grid.cols;
        out["rows"] = q.grid.rows;
        out["aspect"] = q.view_aspect;
        out["view_cone_deg"] = q.view_cone_deg;
        out["rule"] = q.describe();
        return out;
      }, "the quilt this display asks for: views, cols, rows, aspect, view_cone_deg, rule")
      .def_property_readonly("figures", [](const PyDisplay& d) {
        const nlohmann::ordered_json j = display::figures_json({.cal = d.calibration, .path = d.name});
        return py::module_::import("json").attr("loads")(j.dump());
      }, "every figure `lfd info --json` prints, as a dict")
      .def("__repr__", [](const PyDisplay& d) {
        return "<lfd.Display " + d.name + " " + std::to_string(d.calibration.display.screen_w) + "x" +
               std::to_string(d.calibration.display.screen_h) + ">";
      });
}

}  // namespace lfd::python
