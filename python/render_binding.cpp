// lfd.render_quilt, lfd.render_view and lfd.interlace (python/lfd/__init__.py gives them their
// documented signatures): `lfd render`'s settings from keyword arguments, the render with the
// GIL released.
#include <pybind11/stl.h>

#include "display/lens_model.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"
#include "python/display_binding.hpp"
#include "python/render_call.hpp"
#include "python/scene_binding.hpp"
#include "util/error.hpp"

namespace py = pybind11;

namespace lfd::python {
namespace {

// `value` as a T, or InputError naming the keyword.
template <typename T>
T keyword_value(const py::handle& value, const std::string& key, const char* what) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw_input_error("{}: {} is not {}", key, py::repr(value).cast<std::string>(), what);
  }
}

}  // namespace

lightfield::RenderSettings settings_of(const py::dict& keywords) {
  lightfield::RenderSettings s;
  for (const auto& [key_handle, value] : keywords) {
    const std::string key = py::str(key_handle);
    if (value.is_none()) continue;
    if (key == "method") {
      s.method = keyword_value<std::string>(value, key, "a method name");
      s.method_given = true;
    } else if (key == "views") s.views = keyword_value<int>(value, key, "an integer");
    else if (key == "cols") s.cols = keyword_value<int>(value, key, "an integer");
    else if (key == "rows") s.rows = keyword_value<int>(value, key, "an integer");
    else if (key == "size") {
      const auto wh = keyword_value<std::pair<int, int>>(value, key, "(width, height)");
      s.size = display::ViewSize{wh.first, wh.second};
    } else if (key == "view_cone") s.view_cone_deg = keyword_value<double>(value, key, "a number of degrees");
    else if (key == "camera") {
      // cam.json's fields (render/camera_json.hpp), read by the file's own parser.
      const std::string text = py::module_::import("json").attr("dumps")(value).cast<std::string>();
      s.camera = render::parse_camera_json(text, "camera");
    } else if (key == "orbit") s.orbit_deg = keyword_value<float>(value, key, "a number of degrees");
    else if (key == "focal_distance") s.focal_distance = keyword_value<float>(value, key, "a number");
    else if (key == "chunks") s.planes.chunks = keyword_value<int>(value, key, "an integer");
    else if (key == "plane_scale") s.planes.plane_scale = keyword_value<int>(value, key, "an integer");
    else if (key == "shift") s.planes.d_shift = keyword_value<float>(value, key, "a number");
    else if (key == "filter") s.filter = keyword_value<std::string>(value, key, "nearest or bilinear");
    else if (key == "precision") s.precision = keyword_value<std::string>(value, key, "u8, f16 or f32");
    else if (key == "binning") s.binning = keyword_value<std::string>(value, key, "mixed or quantile");
    else if (key == "split_levels") s.split_levels = keyword_value<int>(value, key, "an integer");
    else if (key == "no_plane_lowpass") s.no_plane_lowpass = keyword_value<bool>(value, key, "True or False");
    else if (key == "background") {
      const auto rgb = keyword_value<std::array<float, 3>>(value, key, "(r, g, b) in [0, 1]");
      s.background = glm::vec3(rgb[0], rgb[1], rgb[2]);
    } else if (key == "raster") {
      s.raster = keyword_value<std::string>(value, key, "hardware, compute or auto");
      s.raster_given = true;
    } else
      throw_input_error("{}: not a setting of lfd render (docs/python.md)", key);
  }
  return s;
}

namespace {

RenderCall call_of(const PyScene& scene, const PyDisplay* display, const py::dict& keywords, const std::string& backend) {
  RenderCall call{scene.scene, scene.name, std::nullopt, settings_of(keywords), backend};
  if (display) call.display = display->calibration;
  return call;
}

// The panel of a quilt for a display, as `lfd interlace` makes it from the quilt's file.
Image8 interlace_quilt(const PyQuilt& quilt, const display::Calibration& calibration, const std::string& blend,
                       bool overscan, const std::string& backend) {
  const display::LensModel lens(calibration.display, calibration.correction);
  interlace::InterlaceOptions options;
  options.blend = interlace::parse_view_blend(blend);
  options.overscan = overscan;
  if (backend != "cpu" && backend != "gl") throw_input_error("backend: '{}' is not cpu or gl", backend);
  if (backend == "gl") use_gl_context();
  return to_uint8(lightfield::interlace_panel(to_float(quilt.image), quilt.layout, lens, options,
                                              backend == "gl" ? lightfield::Backend::kGl : lightfield::Backend::kCpu));
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render_defaults", [] {
    const lightfield::RenderSettings s;
    py::dict d;
    d["chunks"] = s.planes.chunks;
    d["plane_scale"] = s.planes.plane_scale;
    d["precision"] = s.precision;
    d["binning"] = s.binning;
    d["orbit"] = s.orbit_deg;
    return d;
  }, "The defaults of `lfd render`'s settings that have one (the others: chosen by the view plan).");
  m.def(
      "render_quilt",
      [](const PyScene& scene, const PyDisplay* display, const py::dict& keywords, const std::string& backend) {
        const RenderCall call = call_of(scene, display, keywords, backend);
        py::gil_scoped_release release;
        return render_quilt(call);
      },
      py::arg("scene"), py::arg("display").none(true), py::arg("settings"), py::arg("backend"));
  m.def(
      "render_view",
      [](const PyScene& scene, int view, const PyDisplay* display, const py::dict& keywords, const std::string& backend) {
        const RenderCall call = call_of(scene, display, keywords, backend);
        Image8 image;
        {
          py::gil_scoped_release release;
          image = render_view(call, view);
        }
        return image_array(std::move(image));
      },
      py::arg("scene"), py::arg("view"), py::arg("display").none(true), py::arg("settings"), py::arg("backend"));
  m.def(
      "interlace",
      [](const PyQuilt& quilt, const PyDisplay& display, const std::string& blend, bool overscan,
         const std::string& backend) {
        Image8 panel;
        {
          py::gil_scoped_release release;
          panel = interlace_quilt(quilt, display.calibration, blend, overscan, backend);
        }
        return image_array(std::move(panel));
      },
      py::arg("quilt"), py::arg("display"), py::arg("blend") = "nearest", py::arg("overscan") = false,
      py::arg("backend") = "cpu", "The panel image (screen H x W x 3 uint8) of a quilt for a display.");
  m.def("_as_numpy", &as_numpy, "torch tensors through DLPack, anything else as it is");
  m.def("release_gl_devices", [] {
    py::gil_scoped_release release;
    release_gl_devices();
  });
}

}  // namespace lfd::python
