#pragma once
// The views a display asks for around a scene's framing, as the direct-panel benchmarks and the
// eye-photograph comparison lay them out (docs/performance.md "Direct panel rendering"): the
// display's quilt (its recommended view count unless `views` is given, grid and cone), views of
// `view_height` rows at the panel's aspect, the base camera from the scene's framing, and the
// quilt geometry and layout of those views. One place, so every side of a comparison sees the
// same views.
#include <optional>

#include "display/display_quilt.hpp"
#include "lightfield/light_field_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"

namespace lfd::lightfield {

struct DisplayViews {
  display::DisplayQuilt quilt;
  display::ViewSize size;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

DisplayViews views_for_display(const display::Calibration& calibration, const LightFieldScene& scene,
                               int view_height, std::optional<int> views = std::nullopt);

}  // namespace lfd::lightfield
