// Per-view direct (interlace/view_masks.hpp): each quilt view rasterised only where the panel
// reads it, then interlaced, must give the panel of the full per-view quilt, on a small display
// with a real unit's lens and on a Gen3 one, with nearest and linear view blending.
#include "interlace/view_masks.hpp"

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "display/visual_json.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "tests/support/small_displays.hpp"
#include "tests/test_data.hpp"

namespace lfd::interlace {
namespace {

struct Fixture {
  scene::GaussianScene scene;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};

// Views larger than the panel needs (as a real quilt's are), so the masks leave pixels out.
Fixture fixture(int views, int width, int height) {
  render::SceneGeneratorOptions g;
  g.count = 3000;
  Fixture f;
  f.scene = render::generate_scene(g);
  const render::CameraSpec spec = render::frame_scene(f.scene);
  const render::Camera base = render::camera_from_spec(spec, width, height);
  f.geometry = render::make_quilt_geometry(base, glm::length(spec.look_at - spec.position), 40.0f, views);
  f.layout = render::make_quilt_layout(f.geometry, 4, (views + 3) / 4);
  return f;
}

void expect_same_panel(const display::DisplayCalibration& cal, ViewBlend blend, int width, int height) {
  const display::LensModel lens(cal);
  const Fixture f = fixture(8, width, height);
  InterlaceOptions options;
  options.blend = blend;
  const Interlacer interlacer(lens, f.layout, options);
  const ViewMasks masks = view_masks(interlacer);
  ASSERT_EQ(masks.masks.size(), 8u);
  ASSERT_EQ(masks.width, width);
  ASSERT_EQ(masks.height, height);
  // The masks leave something out (else the test proves nothing) and keep something in.
  EXPECT_GT(masks.fraction_in(), 0.05);
  EXPECT_LT(masks.fraction_in(), 0.95);

  const ImageF full = render::render_quilt_per_view(f.scene, f.geometry, f.layout);
  const ImageF masked = render::render_quilt_per_view_masked(f.scene, f.geometry, f.layout, masks.masks);
  // The quilts differ where the masks leave pixels out ...
  size_t quilt_differs = 0;
  for (size_t i = 0; i < full.pixels.size(); ++i) quilt_differs += full.pixels[i] != masked.pixels[i];
  EXPECT_GT(quilt_differs, 0u);
  // ... and the panels do not differ at all.
  const ImageF a = interlacer.interlace(full), b = interlacer.interlace(masked);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  size_t panel_differs = 0, lit = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    panel_differs += a.pixels[i] != b.pixels[i];
    lit += a.pixels[i] > 0.01f;
  }
  EXPECT_EQ(panel_differs, 0u);
  EXPECT_GT(lit, a.pixels.size() / 4);  // the scene fills the panel, not black
}

TEST(ViewMasks, MaskedPerViewInterlacesToTheUnmaskedPanel) {
  expect_same_panel(test::small_lkg_2k(0.1), ViewBlend::kNearest, 400, 250);
}

TEST(ViewMasks, MaskedPerViewInterlacesToTheUnmaskedPanelWithLinearBlending) {
  expect_same_panel(test::small_lkg_2k(0.1), ViewBlend::kLinear, 400, 250);
}

TEST(ViewMasks, MaskedPerViewInterlacesToTheUnmaskedPanelOnGen3Cells) {
  expect_same_panel(test::small_gen3_portrait_template(), ViewBlend::kNearest, 270, 480);
}

}  // namespace
}  // namespace lfd::interlace
