#pragma once
// A test quilt in which every view shows its own number on a colour that changes with the
// view index: photographed through the display, the number read tells which view a camera
// position sees, so a scrambled calibration is obvious at a glance.
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::pipeline {

// `layout` must have width/height set. Values in [0, 1], row 0 = top.
ImageF make_numbered_quilt(const render::QuiltLayout& layout);

}  // namespace lfd::pipeline
