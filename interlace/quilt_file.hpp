#pragma once
// The tiling of a quilt image on disk: from the `_qs{C}x{R}a{aspect}` in its name unless the
// user gives it (docs/file-formats.md "Quilts").
#include <filesystem>
#include <optional>

#include "render/quilt_layout.hpp"

namespace lfd::interlace {

struct QuiltOverrides {
  std::optional<int> cols, rows, views;
  std::optional<double> aspect;
};

// Without a name tag or overrides the tiling is unknown: InputError naming the file. The
// aspect defaults to the display's (what Looking Glass software renders tiles with).
render::QuiltLayout resolve_quilt_layout(const std::filesystem::path& path, int width, int height,
                                         const QuiltOverrides& overrides, double display_aspect);

}  // namespace lfd::interlace
