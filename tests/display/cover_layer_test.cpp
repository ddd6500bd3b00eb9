// The cover layer (display/lens_relations.hpp, cover_rays.hpp, cover_layer.hpp): the
// exact refracted ray checked against Snell's law written out with angles, against the
// paraxial apparent depth t (1 - 1/n), and the two directions of tracing against each other.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "display/cover_layer.hpp"
#include "display/cover_rays.hpp"
#include "display/lens_relations.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

constexpr CoverLayer kBlock{0.02, 1.49};  // a 2 cm acrylic block

TEST(CoverLayer, TheExactRayObeysSnellAtTheFrontFaceAndReachesTheViewer) {
  for (const auto& [dx, dy, dz] : {std::array{0.25, 0.03, 0.5}, std::array{-0.1, 0.12, 0.45},
                                   std::array{0.6, -0.2, 0.4}, std::array{0.001, 0.0, 0.6}}) {
    const double d = cover_seen_distance(dx, dy, dz, kBlock);
    const double tan_air = std::hypot(dx, dy) / d;
    // Snell with angles: the in-slab angle from sin(theta_air) = n sin(theta_slab).
    const double theta_air = std::atan(tan_air);
    const double theta_slab = std::asin(std::sin(theta_air) / kBlock.refractive_index);
    // The path: across the slab at theta_slab, then through air at theta_air, lands on C.
    const double lateral = kBlock.thickness_m * std::tan(theta_slab) +
                           (dz - kBlock.thickness_m) * std::tan(theta_air);
    EXPECT_NEAR(lateral, std::hypot(dx, dy), 1e-12) << dx << " " << dy << " " << dz;
  }
}

TEST(CoverLayer, ParaxiallyThePanelAppearsNearerByTTimesOneMinusOneOverN) {
  const double shift = kBlock.thickness_m * (1.0 - 1.0 / kBlock.refractive_index);
  EXPECT_DOUBLE_EQ(kBlock.apparent_shift_m(), shift);
  // Straight ahead the exact distance is the paraxial one.
  EXPECT_NEAR(cover_seen_distance(0.0, 0.0, 0.5, kBlock), 0.5 - shift, 1e-15);
  // Off axis the exact ray differs by -t (n^2 - 1) tan^2 / (2 n^3) to leading order: the
  // second-order term checked at 5 degrees (to 2 %), and its size at 30 degrees.
  const double n = kBlock.refractive_index, t = kBlock.thickness_m;
  for (double deg : {5.0, 30.0}) {
    const double dz = 0.5, tan_a = std::tan(deg * std::numbers::pi / 180.0);
    // A viewer at the offset whose exact air direction is tan_a (built from the path).
    const double tan_s = std::tan(std::asin(std::sin(std::atan(tan_a)) / n));
    const double dx = t * tan_s + (dz - t) * tan_a;
    const double exact_minus_paraxial = cover_seen_distance(dx, 0.0, dz, kBlock) - (dz - shift);
    const double leading = -t * (n * n - 1) * tan_a * tan_a / (2 * n * n * n);
    if (deg == 5.0) EXPECT_NEAR(exact_minus_paraxial / leading, 1.0, 0.02);
    if (deg == 30.0) EXPECT_LT(exact_minus_paraxial, -0.8 * t * 0.05);  // > 0.8 mm: not negligible
  }
}

TEST(CoverLayer, ACameraStraightAheadSeesTheSameFractionWithAndWithoutIt) {
  const double lines = -0.14, cone = 40.0;
  EXPECT_DOUBLE_EQ(seen_fraction_through_cover(0.0, 0.0, 0.5, kBlock, lines, cone), 0.5);
  // Off axis it matters: 0.4 m to the side of a point at 0.5 m, 0.0186 of the cone (nearly
  // four times the center bar) before any camera pose absorbs it. By hand: (0.40 - 0.14 x 0.1) k
  // (1/D - 1/0.5), k = 1 / (2 tan 20 deg) = 1.3737, D = 0.4914 m the fixed point of
  // D = (0.5 - t) + t / sqrt(n^2 + (n^2 - 1) (d/D)^2), t = 0.02, n = 1.49, d = |(0.40, 0.1)|.
  const double off = seen_fraction_through_cover(0.40, 0.1, 0.5, kBlock, lines, cone) -
                     seen_fraction(0.40, 0.1, 0.5, lines, cone);
  EXPECT_NEAR(off, 0.0186, 0.0005);
}

TEST(CoverLayer, TracingFromTheCameraAndFromThePanelAgree) {
  // The simulator traces a camera ray forward through Snell (panel_hit_through_cover);
  // registration and the solver go from the panel point back (the fixed point). Same ray.
  const Point3 camera{0.21, -0.05, 0.47};
  for (const Point3 dir : {Point3{-0.4, 0.1, -1.0}, Point3{0.05, 0.3, -1.0}, Point3{-0.7, -0.2, -1.0}}) {
    const PanelHit hit = panel_hit_through_cover(camera, dir, kBlock);
    const double dx = camera.x - hit.x, dy = camera.y - hit.y;
    const double d = cover_seen_distance(dx, dy, camera.z, kBlock);
    EXPECT_NEAR(dx / d, hit.tan_x, 1e-12);
    EXPECT_NEAR(dy / d, hit.tan_y, 1e-12);
    // The exit point lies on the camera's ray.
    const Point3 e = cover_exit_point({hit.x, hit.y, 0.0}, camera, kBlock);
    EXPECT_NEAR(e.z, kBlock.thickness_m, 1e-15);
    const double s = (e.z - camera.z) / dir.z;
    EXPECT_NEAR(e.x, camera.x + s * dir.x, 1e-12);
    EXPECT_NEAR(e.y, camera.y + s * dir.y, 1e-12);
  }
  // No cover: the straight line.
  const PanelHit bare = panel_hit_through_cover(camera, {-0.4, 0.1, -1.0}, CoverLayer{});
  EXPECT_NEAR(bare.x, camera.x - 0.4 * camera.z, 1e-15);
}

TEST(CoverLayer, FamiliesHaveDefaultsAndABarePanelHasNone) {
  const auto portrait = read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  EXPECT_EQ(cover_layer_for_family(portrait).family, "Portrait");
  EXPECT_GT(cover_layer_for_family(portrait).cover.thickness_m, 0.01);
  // A Gen1 unit read over HID has a bare number as serial: its panel names the family.
  const auto gen1 = read_visual_json(test::fixture_calibration("gen1-hid-00297.visual.json"));
  EXPECT_EQ(cover_layer_for_family(gen1).family, "Gen1 8.9\"");
  DisplayCalibration unknown = portrait;
  unknown.serial = "X";
  unknown.screen_w = 1000;
  EXPECT_FALSE(cover_layer_for_family(unknown).cover.present());
}

TEST(CoverLayer, CalibrationJsonKeepsItAndVisualJsonStaysAsItWas) {
  Calibration c;
  c.display = read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  const std::string visual_before = to_visual_json(c.display).dump();
  c.display.cover = {0.018, 1.5};
  EXPECT_EQ(to_visual_json(c.display).dump(), visual_before);  // no field visual.json lacks
  const Calibration back = parse_calibration(to_json(c).dump(), "cal.json");
  EXPECT_EQ(back.display.cover.thickness_m, 0.018);
  EXPECT_EQ(back.display.cover.refractive_index, 1.5);
  // A bare panel writes no "cover"; a file without one reads as bare.
  c.display.cover = {};
  EXPECT_FALSE(to_json(c).contains("cover"));
  EXPECT_FALSE(parse_calibration(to_json(c).dump(), "cal.json").display.cover.present());
  EXPECT_THROW(parse_calibration(R"({"format":"lfd-calibration","version":1,"display":)" +
                                     visual_before + R"(,"cover":{"thickness_m":-1}})",
                                 "cal.json"),
               InputError);
}

}  // namespace
}  // namespace lfd::display
