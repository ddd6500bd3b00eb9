#include "python/quilt_binding.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "interlace/quilt_file.hpp"
#include "interlace/quilt_file_name.hpp"
#include "python/arrays.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace lfd::python {
namespace {

// The tiling of an image of `width` x `height` in cols x rows tiles; the aspect defaults to the
// tiles' own.
render::QuiltLayout layout_of(int width, int height, int cols, int rows, std::optional<int> views,
                              std::optional<double> aspect) {
  render::QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = views.value_or(cols * rows);
  q.width = width;
  q.height = height;
  q.aspect = aspect.value_or(rows > 0 && cols > 0 && height >= rows ? double(width / cols) / (height / rows) : 1.0);
  q.check("Quilt");
  return q;
}

}  // namespace

void bind_quilt(py::module_& m) {
  py::class_<PyQuilt>(m, "Quilt", "A light-field quilt: views in a cols x rows grid, view 0 bottom-left.")
      .def(py::init([](const py::handle& image, int cols, int rows, std::optional<double> aspect, std::optional<int> views) {
             Image8 pixels = checked_rgb8_image(image, "image");
             const render::QuiltLayout q = layout_of(pixels.width, pixels.height, cols, rows, views, aspect);
             return PyQuilt{std::move(pixels), q};
           }),
           py::arg("image"), py::arg("cols"), py::arg("rows"), py::arg("aspect") = py::none(),
           py::arg("views") = py::none(), "A quilt from an H x W x 3 uint8 array.")
      .def_static(
          "load",
          [](const std::filesystem::path& path, std::optional<int> cols, std::optional<int> rows,
             std::optional<int> views, std::optional<double> aspect) {
            Image8 pixels = read_image(path, 3);
            interlace::QuiltOverrides overrides{cols, rows, views, aspect};
            const double tile_aspect = double(pixels.width) / pixels.height;
            const render::QuiltLayout q =
                interlace::resolve_quilt_layout(path, pixels.width, pixels.height, overrides, tile_aspect);
            return PyQuilt{std::move(pixels), q};
          },
          py::arg("path"), py::arg("cols") = py::none(), py::arg("rows") = py::none(), py::arg("views") = py::none(),
          py::arg("aspect") = py::none(), "A quilt file; the tiling from its _qsCxRaA name unless given.")
      .def_property_readonly("image", [](py::object self) { return image_view(self.cast<const PyQuilt&>().image, self); },
                             "H x W x 3 uint8, rows top-down (shares the quilt's memory)")
      .def_property_readonly("cols", [](const PyQuilt& q) { return q.layout.cols; })
      .def_property_readonly("rows", [](const PyQuilt& q) { return q.layout.rows; })
      .def_property_readonly("views", [](const PyQuilt& q) { return q.layout.views; })
      .def_property_readonly("aspect", [](const PyQuilt& q) { return q.layout.aspect; })
      .def_property_readonly("tile_size", [](const PyQuilt& q) {
        return py::make_tuple(q.layout.tile_width(), q.layout.tile_height());
      }, "(width, height) of one tile")
      .def(
          "save",
          [](const PyQuilt& q, const std::string& path) {
            const std::string written = interlace::quilt_file_name(path, q.layout, "path");
            write_png(written, q.image);
            return written;
          },
          py::arg("path"), "Writes a PNG named with the _qsCxRaA tiling (added unless the name has it); returns the name.")
      .def("__repr__", [](const PyQuilt& q) {
        return "<lfd.Quilt " + std::to_string(q.layout.views) + " views in " + std::to_string(q.layout.cols) + "x" +
               std::to_string(q.layout.rows) + " tiles of " + std::to_string(q.layout.tile_width()) + "x" +
               std::to_string(q.layout.tile_height()) + ">";
      });
}

}  // namespace lfd::python
