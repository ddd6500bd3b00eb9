#pragma once
// Array arguments checked as lfd checks a file's fields (docs/python.md "Arrays"): a floating
// dtype, the shape expected, finite values; anything else is lfd.InputError (a ValueError)
// naming the argument. Accepts what numpy.asarray accepts (the package's Python side turns torch
// tensors into numpy arrays through DLPack first).
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "util/image.hpp"

namespace lfd::python {

using FloatArray = pybind11::array_t<float, pybind11::array::c_style | pybind11::array::forcecast>;

// `value` as numpy sees it: a torch tensor (detached, on the CPU) through DLPack
// (numpy.from_dlpack), anything else as it is.
pybind11::object as_numpy(const pybind11::handle& value);

// One axis of an expected shape: a fixed length, or any length named by `label` ("N"); axes with
// the same label must agree.
struct Axis {
  long length = -1;
  const char* label = nullptr;
};

// `value` as a C-contiguous float32 array of `shape` (float16/32/64 in; a copy only when the
// dtype or layout differ). InputError "<name>: ..." for a non-floating dtype, another shape, or a
// value that is NaN or infinite.
FloatArray checked_float_array(const pybind11::handle& value, const std::string& name, const std::vector<Axis>& shape);

// The lengths the labelled axes took in the arrays checked so far (shared by one call's
// arguments): "N" must be the same for means and rotations.
class AxisLengths {
 public:
  // InputError naming `name` when `label` already has another length.
  void bind(const char* label, long length, const std::string& name);
 private:
  std::vector<std::pair<std::string, std::pair<long, std::string>>> seen_;
};
FloatArray checked_float_array(const pybind11::handle& value, const std::string& name, const std::vector<Axis>& shape,
                               AxisLengths& lengths);

// An H x W x 3 uint8 image array (a quilt, a panel): InputError naming `name` otherwise.
Image8 checked_rgb8_image(const pybind11::handle& value, const std::string& name);

// An image as an H x W x C uint8 numpy array that shares the memory of `owner`'s image (no copy).
pybind11::array image_view(const Image8& image, const pybind11::handle& owner);
// An image moved into a new numpy array (the array owns it).
pybind11::array image_array(Image8 image);

}  // namespace lfd::python
