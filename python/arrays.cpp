#include "python/arrays.hpp"

#include <cmath>
#include <cstring>
#include <memory>

#include <fmt/format.h>

#include "util/error.hpp"

namespace py = pybind11;

namespace lfd::python {
namespace {

std::string shape_text(const std::vector<Axis>& shape) {
  std::string text = "(";
  for (size_t k = 0; k < shape.size(); ++k) {
    if (k) text += ", ";
    text += shape[k].length >= 0 ? std::to_string(shape[k].length) : std::string(shape[k].label);
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) {
    if (k) text += ", ";
    text += std::to_string(a.shape(k));
  }
  return text + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

py::object as_numpy(const py::handle& value) {
  py::object v = py::reinterpret_borrow<py::object>(value);
  if (py::isinstance<py::array>(v) || !py::hasattr(v, "__dlpack__")) return v;
  // torch refuses to export a tensor that requires grad, or one on a GPU: a training loop's
  // parameters are both; lfd reads a copy of their values.
  if (py::hasattr(v, "detach")) v = v.attr("detach")();
  if (py::hasattr(v, "cpu")) v = v.attr("cpu")();
  return py::module_::import("numpy").attr("from_dlpack")(v);
}

void AxisLengths::bind(const char* label, long length, const std::string& name) {
  for (const auto& [seen_label, seen] : seen_)
    if (seen_label == label) {
      if (seen.first != length)
        throw_input_error("{}: {} = {} but {} has {} = {}", name, label, length, seen.second, label, seen.first);
      return;
    }
  seen_.push_back({label, {length, name}});
}

FloatArray checked_float_array(const py::handle& value, const std::string& name, const std::vector<Axis>& shape) {
  AxisLengths lengths;
  return checked_float_array(value, name, shape, lengths);
}

FloatArray checked_float_array(const py::handle& value, const std::string& name, const std::vector<Axis>& shape,
                               AxisLengths& lengths) {
  if (value.is_none()) throw_input_error("{}: required, an array of shape {}", name, shape_text(shape));
  py::array any;
  try {
    any = py::array::ensure(as_numpy(value));
  } catch (const py::error_already_set&) {
  }
  if (!any) throw_input_error("{}: not an array (expected shape {} of floats)", name, shape_text(shape));
  const char kind = any.dtype().kind();
  if (kind != 'f')
    throw_input_error("{}: dtype {} is not floating point (float32 expected)", name,
                      py::str(any.dtype()).cast<std::string>());
  bool fits = any.ndim() == py::ssize_t(shape.size());
  for (size_t k = 0; fits && k < shape.size(); ++k)
    fits = shape[k].length < 0 || any.shape(k) == shape[k].length;
  if (!fits) throw_input_error("{}: shape {}, expected {}", name, shape_text(any), shape_text(shape));
  for (size_t k = 0; k < shape.size(); ++k)
    if (shape[k].length < 0) lengths.bind(shape[k].label, long(any.shape(k)), name);
  FloatArray floats = FloatArray::ensure(any);
  if (!floats) throw py::error_already_set();
  const float* data = floats.data();
  const size_t count = size_t(floats.size());
  const size_t row = shape.empty() || floats.ndim() == 0 ? 1 : count / std::max<size_t>(1, size_t(floats.shape(0)));
  for (size_t i = 0; i < count; ++i)
    if (!std::isfinite(data[i]))
      throw_input_error("{}: element {} ({}) is {}", name, row > 1 ? fmt::format("[{}]", i / row) : fmt::format("{}", i),
                        data[i], std::isnan(data[i]) ? "NaN" : "infinite");
  return floats;
}

Image8 checked_rgb8_image(const py::handle& value, const std::string& name) {
  py::array any = py::array::ensure(as_numpy(value));
  if (!any) throw_input_error("{}: not an array (expected an H x W x 3 uint8 image)", name);
  if (any.dtype().kind() != 'u' || any.dtype().itemsize() != 1)
    throw_input_error("{}: dtype {} is not uint8 (an H x W x 3 uint8 image expected)", name,
                      py::str(any.dtype()).cast<std::string>());
  if (any.ndim() != 3 || any.shape(2) != 3 || any.shape(0) < 1 || any.shape(1) < 1)
    throw_input_error("{}: shape {}, expected (H, W, 3)", name, shape_text(any));
  const auto pixels = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(any);
  Image8 image(int(any.shape(1)), int(any.shape(0)), 3);
  std::memcpy(image.pixels.data(), pixels.data(), image.pixels.size());
  return image;
}

py::array image_view(const Image8& image, const py::handle& owner) {
  return py::array(py::dtype::of<uint8_t>(), {image.height, image.width, image.channels},
                   {image.width * image.channels, image.channels, 1}, image.pixels.data(), owner);
}

py::array image_array(Image8 image) {
  auto* held = new Image8(std::move(image));
  py::capsule owner(held, [](void* p) { delete static_cast<Image8*>(p); });
  return image_view(*held, owner);
}

}  // namespace lfd::python
