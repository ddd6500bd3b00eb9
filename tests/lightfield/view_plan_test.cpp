// The one view plan (lightfield/view_plan.hpp): each field's fallbacks, in the order its header
// states, against the display model's own rules (display::quilt_for_display and friends).
#include <cmath>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "lightfield/scene_framing.hpp"
#include "lightfield/view_plan.hpp"
#include "tests/lightfield/light_field_test_scenes.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "tests/test_data.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {
namespace {

TEST(ViewPlan, ADisplayDecidesViewsConeGridAndSize) {
  const display::Calibration calibration = test::portrait_calibration();
  ViewRequest request;
  request.display = &calibration;
  request.view_height = 200;
  const ViewPlan plan = plan_views(request, &test_gaussians());
  const display::DisplayQuilt expected = display::quilt_for_display(calibration);
  const display::ViewSize size = display::view_size_for_display(expected, 200);
  ASSERT_TRUE(plan.display_quilt);
  EXPECT_EQ(plan.views, expected.views);
  EXPECT_DOUBLE_EQ(plan.view_cone_deg, expected.view_cone_deg);
  EXPECT_EQ(plan.layout.cols, expected.grid.cols);
  EXPECT_EQ(plan.layout.rows, expected.grid.rows);
  EXPECT_EQ(plan.geometry.base.width, size.width);
  EXPECT_EQ(plan.geometry.base.height, 200);
  EXPECT_EQ(plan.geometry.views, expected.views);
  EXPECT_NEAR(plan.geometry.view_cone_rad, float(expected.view_cone_deg * M_PI / 180.0), 1e-6);
  // The framing is made for the views' aspect, and its look-at point is the focal plane.
  const render::CameraSpec spec = scene_framing(test_gaussians(), render::kDefaultFovYDeg, 0.0f,
                                                float(size.width) / float(size.height));
  EXPECT_FLOAT_EQ(plan.geometry.focal_distance, glm::length(spec.look_at - spec.position));
}

TEST(ViewPlan, TheRequestOverridesTheDisplay) {
  const display::Calibration calibration = test::portrait_calibration();
  ViewRequest request;
  request.display = &calibration;
  request.views = 12;
  request.view_cone_deg = 30.0;
  request.cone_scale = 1.5;  // the viewer's depthiness
  request.size = display::ViewSize{64, 48};
  request.focal_distance = 2.0f;
  request.focal_scale = 0.5f;
  request.grid = display::QuiltGrid{4, 3};
  const ViewPlan plan = plan_views(request, &test_gaussians());
  EXPECT_EQ(plan.views, 12);
  EXPECT_EQ(plan.display_quilt->views, 12) << "--views reaches the display's quilt too";
  EXPECT_DOUBLE_EQ(plan.view_cone_deg, 45.0);
  EXPECT_EQ(plan.geometry.base.width, 64);
  EXPECT_EQ(plan.geometry.base.height, 48);
  EXPECT_FLOAT_EQ(plan.geometry.focal_distance, 1.0f);
  EXPECT_EQ(plan.layout.cols, 4);
  EXPECT_EQ(plan.layout.rows, 3);
}

TEST(ViewPlan, ACameraWithItsOwnSizeKeepsItOnADisplay) {
  const display::Calibration calibration = test::portrait_calibration();
  ViewRequest request;
  request.display = &calibration;
  request.camera = scene_framing(test_gaussians());
  request.camera->width = 100;
  request.camera->height = 50;
  const ViewPlan plan = plan_views(request);
  EXPECT_EQ(plan.geometry.base.width, 100);
  EXPECT_EQ(plan.geometry.base.height, 50);
}

TEST(ViewPlan, WithoutADisplayTheDefaultsDecide) {
  ViewRequest request;
  request.size = display::ViewSize{32, 24};
  const ViewPlan plan = plan_views(request, &test_voxels());
  EXPECT_FALSE(plan.display_quilt);
  EXPECT_EQ(plan.views, kDefaultViewCount);
  EXPECT_DOUBLE_EQ(plan.view_cone_deg, kDefaultViewConeDeg);
  const display::QuiltGrid grid = display::quilt_grid_for_views(kDefaultViewCount, 32.0 / 24.0);
  EXPECT_EQ(plan.layout.cols, grid.cols);
  EXPECT_EQ(plan.layout.rows, grid.rows);
}

TEST(ViewPlan, ABaseCameraIsUsedAsItIs) {
  const render::CameraSpec spec = scene_framing(test_gaussians());
  ViewRequest request;
  request.base_camera = render::camera_from_spec(spec, 40, 30);
  request.focal_distance = 3.0f;
  request.views = 5;
  request.grid = display::QuiltGrid{5, 1};
  const ViewPlan plan = plan_views(request);
  EXPECT_EQ(plan.geometry.base.width, 40);
  EXPECT_FLOAT_EQ(plan.geometry.focal_distance, 3.0f);
  EXPECT_EQ(plan.layout.cols, 5);
  request.focal_distance.reset();
  EXPECT_THROW(plan_views(request), std::logic_error);
}

TEST(ViewPlan, BadRequestsNameTheirField) {
  ViewRequest request;
  request.size = display::ViewSize{32, 24};
  request.views = 300;
  try {
    plan_views(request, &test_gaussians());
    FAIL() << "300 views accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("views: ", 0), 0u) << e.what();
  }
  request.views = 10;
  request.grid = display::QuiltGrid{3, 3};
  try {
    plan_views(request, &test_gaussians());
    FAIL() << "3x3 tiles accepted for 10 views";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "grid: 3x3 tiles cannot hold 10 views");
  }
  ViewRequest nothing_to_frame;
  EXPECT_THROW(plan_views(nothing_to_frame), std::logic_error);
}

TEST(ViewPlan, TheQuiltNamesTheDisplaysViewAspectNotItsRoundedTiles) {
  const display::Calibration gen3 =
      display::read_calibration(test::project_data() / "displays" / "16in-landscape-gen3.visual.json");
  ViewRequest request;
  request.display = &gen3;
  const ViewPlan plan = plan_views(request, &test_gaussians());
  EXPECT_EQ(plan.geometry.base.width, 910);  // 512 rows at 16:9 round to 910 columns (1.7773)
  EXPECT_EQ(plan.geometry.base.height, 512);
  EXPECT_DOUBLE_EQ(plan.layout.aspect, 3840.0 / 2160.0);
  EXPECT_TRUE(render::quilt_suffix(plan.layout.cols, plan.layout.rows, plan.layout.aspect).ends_with("a1.7778"));
  // A size the user chose far from the panel's keeps its own aspect (the interlacer bars it).
  request.size = display::ViewSize{512, 512};
  EXPECT_DOUBLE_EQ(plan_views(request, &test_gaussians()).layout.aspect, 1.0);
  // Without a display the quilt names the camera's aspect.
  EXPECT_DOUBLE_EQ(plan_views(square_views(render::CameraSpec{}, 64, 40.0, 8)).layout.aspect, 1.0);
}

}  // namespace
}  // namespace lfd::lightfield
