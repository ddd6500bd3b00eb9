#pragma once
// lfd.Quilt: a light-field quilt in memory (8-bit RGB, rows top-down) and its tiling.
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::python {

struct PyQuilt {
  Image8 image;
  render::QuiltLayout layout;
};

}  // namespace lfd::python
