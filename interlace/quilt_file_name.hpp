#pragma once
// The name a quilt is written under (lfd render, lfd rgbd-quilt, the Python Quilt.save): the `_qsCxRaA` tiling
// of render/quilt_layout.hpp added to the name the user gave.
#include <string>

#include "render/quilt_layout.hpp"

namespace lfd::interlace {

// `path` with render::quilt_suffix added before the extension (".png" when it has none), or
// `path` itself when its name already carries a tiling, which must then be the quilt's
// (InputError "<option>: '<path>' names a CxR quilt but the quilt is CxR" otherwise).
std::string quilt_file_name(const std::string& path, const render::QuiltLayout& q,
                            const std::string& option = "--out");

}  // namespace lfd::interlace
