// lightfield/render_settings.hpp: one mapping of `lfd render`'s settings for the program and
// Python, with each refusal naming the setting as the caller spells it.
#include <gtest/gtest.h>

#include "lightfield/render_settings.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {
namespace {

std::string refusal(const RenderSettings& s, SettingNames names) {
  try {
    check_render_settings(s, names);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RenderSettings, NamesASettingAsAFlagOrAKeyword) {
  EXPECT_EQ(setting_name(SettingNames::kFlags, "view_cone"), "--view-cone");
  EXPECT_EQ(setting_name(SettingNames::kKeywords, "view_cone"), "view_cone");
  RenderSettings s;
  s.view_cone_deg = 200.0;
  EXPECT_EQ(refusal(s, SettingNames::kFlags), "--view-cone: 200 must lie in (0, 170) degrees");
  EXPECT_EQ(refusal(s, SettingNames::kKeywords), "view_cone: 200 must lie in (0, 170) degrees");
}

TEST(RenderSettings, RefusesColsWithoutRowsAndUnknownChoices) {
  RenderSettings s;
  s.cols = 4;
  EXPECT_EQ(refusal(s, SettingNames::kKeywords), "cols: needs rows too");
  s = RenderSettings{};
  s.binning = "random";
  EXPECT_EQ(refusal(s, SettingNames::kFlags), "--binning: 'random' is not one of mixed, quantile");
  EXPECT_EQ(refusal(RenderSettings{}, SettingNames::kFlags), "");
}

TEST(RenderSettings, MethodFollowsTheSceneKindUnlessAsked) {
  RenderSettings s;  // g2lf by default: V2LF's sweeping planes for voxels
  EXPECT_EQ(renderer_options(s, scene::SceneKind::kVoxels, "v", Backend::kCpu, SettingNames::kFlags).method,
            Method::kSweepingPlanes);
  s.method_given = true;
  EXPECT_THROW(renderer_options(s, scene::SceneKind::kVoxels, "v", Backend::kCpu, SettingNames::kFlags), InputError);
  s = RenderSettings{};
  s.method = "per-view";
  EXPECT_EQ(renderer_options(s, scene::SceneKind::kGaussians, "g", Backend::kCpu, SettingNames::kFlags).method,
            Method::kPerView);
  s.precision = "f16";  // a GPU texture format only
  EXPECT_THROW(renderer_options(s, scene::SceneKind::kGaussians, "g", Backend::kCpu, SettingNames::kFlags), InputError);
  EXPECT_EQ(renderer_options(s, scene::SceneKind::kGaussians, "g", Backend::kGl, SettingNames::kFlags).gl.plane_format,
            gpu::PlaneFormat::kRgba16f);
}

TEST(RenderSettings, TheViewRequestCarriesWhatWasGiven) {
  RenderSettings s;
  s.views = 12;
  s.cols = 4;
  s.rows = 3;
  s.size = display::ViewSize{64, 48};
  s.focal_distance = 2.5f;
  const ViewRequest r = view_request(s, nullptr);
  EXPECT_EQ(r.views, 12);
  ASSERT_TRUE(r.grid);
  EXPECT_EQ(r.grid->cols, 4);
  EXPECT_EQ(r.grid->rows, 3);
  ASSERT_TRUE(r.size);
  EXPECT_EQ(r.size->width, 64);
  EXPECT_FLOAT_EQ(*r.focal_distance, 2.5f);
  EXPECT_FALSE(view_request(RenderSettings{}, nullptr).focal_distance);  // 0: the look-at distance
}

TEST(RenderSettings, TheRasterPathIsTheGlBackendsOnly) {
  RenderSettings s;
  EXPECT_EQ(renderer_options(s, scene::SceneKind::kGaussians, "g", Backend::kGl, SettingNames::kFlags).gl.raster,
            gpu::RasterPath::kHardware);
  s.raster = "compute";
  s.raster_given = true;
  EXPECT_EQ(renderer_options(s, scene::SceneKind::kGaussians, "g", Backend::kGl, SettingNames::kKeywords).gl.raster,
            gpu::RasterPath::kCompute);
  EXPECT_NO_THROW(check_backend_settings(s, false, SettingNames::kFlags));  // gl, or auto falling back
  try {
    check_backend_settings(s, true, SettingNames::kKeywords);
    ADD_FAILURE() << "raster asked of the CPU";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "raster: chooses how the GL backend draws; the CPU backend has no raster paths");
  }
  s.raster = "fast";
  EXPECT_EQ(refusal(s, SettingNames::kFlags), "--raster: 'fast' is not one of hardware, compute, auto");
}

TEST(RenderSettings, TheFrameOfAMovingSceneIsOneOfItsFiles) {
  const scene::SceneSequence moving{"m_%04d.ply", {"m_0000.ply", "m_0001.ply", "m_0002.ply"}};
  RenderSettings s;
  EXPECT_EQ(scene_frame_file(s, moving, true, SettingNames::kFlags), "m_0000.ply");
  s.frame = 2;
  s.frame_given = true;
  EXPECT_EQ(scene_frame_file(s, moving, true, SettingNames::kFlags), "m_0002.ply");
  const auto refusal_of = [&](const scene::SceneSequence& seq, bool is_moving) -> std::string {
    try {
      scene_frame_file(s, seq, is_moving, SettingNames::kFlags);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  s.frame = 3;
  EXPECT_EQ(refusal_of(moving, true), "--frame: 3 is outside the 3 frames of m_%04d.ply");
  s.frame = 0;
  EXPECT_EQ(refusal_of(scene::SceneSequence{"s.ply", {"s.ply"}}, false),
            "--frame: s.ply is one scene; a moving one is a pattern (name_%04d.ply), a folder or a list");
}

}  // namespace
}  // namespace lfd::lightfield
