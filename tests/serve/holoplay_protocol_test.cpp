// The HoloPlay Service commands against the test double: what each command changes, and that a
// bad request gets an error reply and changes nothing.
#include <cmath>

#include <gtest/gtest.h>

#include "serve/holoplay_protocol.hpp"
#include "serve/served_display_json.hpp"
#include "tests/serve/fake_display_service.hpp"
#include "tests/serve/serve_test_support.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;

struct HoloPlayProtocolTest : ::testing::Test {
  ServeLimits limits;
  test::FakeDisplayService fake{{test::fixture_display()}};
  QuiltCache cache{1u << 26, 4};
  MemoryBudget budget{limits.memory_budget_bytes};
  DecodedQuilts decoded{budget, limits};
  HoloPlayProtocol protocol{fake, cache, decoded, budget, limits};
  test::TempDir tmp;

  json call(const json& cmd, const std::vector<std::uint8_t>& bin = {}) {
    json request = {{"cmd", cmd}, {"bin", bin.empty() ? json(nullptr) : json::binary(bin)}};
    return decode_cbor(protocol.handle(encode_cbor(request)), {});
  }
};

TEST_F(HoloPlayProtocolTest, InfoServesTheCalibrationFileAndItsDefaultQuilt) {
  const json reply = call({{"info", json::object()}});
  ASSERT_EQ(reply["error"], 0);
  ASSERT_EQ(reply["devices"].size(), 1u);
  const json& cal = reply["devices"][0]["calibration"];
  const auto& d = test::fixture_display().calibration.display;
  EXPECT_DOUBLE_EQ(cal["pitch"]["value"].get<double>(), d.pitch_lpi);
  EXPECT_DOUBLE_EQ(cal["slope"]["value"].get<double>(), d.slope);
  EXPECT_DOUBLE_EQ(cal["center"]["value"].get<double>(), d.center_periods);
  EXPECT_EQ(cal["screenW"]["value"].get<int>(), d.screen_w);
  EXPECT_EQ(cal["calibrationSource"], "factory visual.json");
  EXPECT_TRUE(cal.contains("fringe"));
  EXPECT_GE(reply["devices"][0]["defaultQuilt"]["tileX"].get<int>(), 1);
  EXPECT_EQ(call({{"init", {{"appid", "x"}}}})["devices"], reply["devices"]);
}

TEST_F(HoloPlayProtocolTest, UniformsAreTheShaderTermsOfTheCalibration) {
  const json reply = call({{"uniforms", json::object()}});
  ASSERT_EQ(reply["error"], 0) << reply.dump();
  ASSERT_EQ(reply["uniforms"].size(), 1u);
  const json& u = reply["uniforms"][0];
  const auto& d = test::fixture_display().calibration.display;
  // The Looking Glass shader's terms, written out: pitch (W / DPI) cos(atan(1 / slope)), H / (W slope).
  const double pitch = d.pitch_lpi * (d.screen_w / d.dpi) * std::cos(std::atan(1.0 / d.slope));
  EXPECT_NEAR(u["pitch"].get<double>(), pitch, 1e-9 * pitch);
  EXPECT_NEAR(u["tilt"].get<double>(), (d.flip_image_x ? -1 : 1) * d.screen_h / (d.screen_w * d.slope), 1e-12);
  EXPECT_DOUBLE_EQ(u["center"].get<double>(), d.center_periods);
  EXPECT_DOUBLE_EQ(u["subp"].get<double>(), 1.0 / (3 * d.screen_w));
  EXPECT_EQ(u["invView"], d.inv_view ? 1 : 0);
  const json shader = call({{"shader", json::object()}});
  EXPECT_EQ(shader["error"], static_cast<int>(HoloPlayError::kUnknownCommand));
  EXPECT_TRUE(fake.recorded().empty());
}

TEST_F(HoloPlayProtocolTest, ShowDecodesTheQuiltBytesExactly) {
  const Image8 quilt = test::pattern_quilt(40, 36);
  const json reply = call({{"show", {{"source", "bindata"}, {"quilt", {{"type", "image"},
                            {"settings", {{"vx", 4}, {"vy", 3}, {"aspect", 0.75}}}}}}}},
                          test::png_bytes(quilt, tmp.path));
  ASSERT_EQ(reply["error"], 0) << reply.dump();
  EXPECT_EQ(fake.last_quilt.pixels, quilt.pixels);
  EXPECT_EQ(fake.last_settings.cols, 4);
  EXPECT_EQ(fake.last_settings.views, 12);
}

TEST_F(HoloPlayProtocolTest, CacheCheckShowDeleteByName) {
  const auto png = test::png_bytes(test::pattern_quilt(8, 8), tmp.path);
  const json settings = {{"vx", 2}, {"vy", 2}, {"aspect", 1.0}};
  EXPECT_EQ(call({{"cache", {{"show", false}, {"quilt", {{"name", "q"}, {"type", "image"}, {"settings", settings}}}}}}, png)["error"], 0);
  EXPECT_TRUE(fake.recorded().empty());
  EXPECT_EQ(call({{"check", {{"name", "q"}}}})["error"], 0);
  EXPECT_EQ(call({{"show", {{"source", "cache"}, {"quilt", {{"name", "q"}}}}}})["error"], 0);
  EXPECT_EQ(fake.recorded().back(), "show_quilt 0 cached quilt q");
  EXPECT_EQ(call({{"delete", {{"name", "q"}}}})["error"], 0);
  EXPECT_EQ(call({{"check", {{"name", "q"}}}})["error"], static_cast<int>(HoloPlayError::kNotFound));
}

TEST_F(HoloPlayProtocolTest, BadRequestsGetErrorRepliesAndChangeNothing) {
  EXPECT_EQ(call({{"launch_missiles", json::object()}})["error"], static_cast<int>(HoloPlayError::kUnknownCommand));
  EXPECT_EQ(call({{"show", {{"quilt", {{"settings", {{"vx", 0}, {"vy", 9}, {"aspect", 1}}}}}}}}, {1, 2, 3})["error"],
            static_cast<int>(HoloPlayError::kBadArgument));
  EXPECT_EQ(call({{"show", {{"quilt", {{"settings", {{"vx", 5}, {"vy", 9}, {"aspect", 1}}}}}}}}, {1, 2, 3})["error"],
            static_cast<int>(HoloPlayError::kBadArgument));  // not an image
  EXPECT_EQ(call({{"wipe", {{"targetDisplay", 7}}}})["error"], static_cast<int>(HoloPlayError::kBadArgument));
  const std::vector<std::uint8_t> garbage = {0xff, 0x00, 0x13, 0x37};
  EXPECT_EQ(decode_cbor(protocol.handle(garbage), {})["error"], static_cast<int>(HoloPlayError::kBadMessage));
  EXPECT_TRUE(fake.recorded().empty());
}

TEST_F(HoloPlayProtocolTest, WipeReachesTheDisplay) {
  EXPECT_EQ(call({{"wipe", json::object()}})["error"], 0);
  EXPECT_EQ(fake.recorded(), std::vector<std::string>{"wipe 0"});
}

}  // namespace
}  // namespace lfd::serve
