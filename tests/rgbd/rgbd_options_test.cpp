// RgbdOptions: bridge.js's defaults, names and ranges; every bad value is a one-line InputError
// naming the field (docs/rgbd.md "Options").
#include "rgbd/rgbd_options.hpp"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "util/error.hpp"

namespace lfd::rgbd {
namespace {

// The message of the InputError `f` throws (empty if it throws none).
template <typename F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

void expect_one_line_naming(const std::string& message, const std::string& field) {
  EXPECT_NE(message.find(field), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(RgbdOptions, DefaultsAreBridgeJss) {
  const RgbdOptions o;
  EXPECT_EQ(o.depth_loc, DepthLocation::right);  // colour left, depth right; bridge.js 2
  EXPECT_EQ(int(o.depth_loc), 2);
  EXPECT_DOUBLE_EQ(o.depthiness, 1.5);
  EXPECT_DOUBLE_EQ(o.focus, 0.0);
  EXPECT_FALSE(o.depth_inversion);
  EXPECT_FALSE(o.chroma_depth);
  EXPECT_DOUBLE_EQ(o.zoom, 1.0);
  EXPECT_DOUBLE_EQ(o.crop_pos_x, 0.0);
  EXPECT_DOUBLE_EQ(o.crop_pos_y, 0.0);
  EXPECT_DOUBLE_EQ(o.depth_cutoff, 0.0);  // bridge.js 0.0.8-alpha.6's DEPTH_CUTOFF default: nothing removed
  EXPECT_NO_THROW(o.check());
}

TEST(RgbdOptions, DepthLocationsByNameAndBridgeJsNumber) {
  EXPECT_EQ(parse_depth_location("top"), DepthLocation::top);
  EXPECT_EQ(parse_depth_location("0"), DepthLocation::top);
  EXPECT_EQ(parse_depth_location("Bottom"), DepthLocation::bottom);
  EXPECT_EQ(parse_depth_location("1"), DepthLocation::bottom);
  EXPECT_EQ(parse_depth_location("RIGHT"), DepthLocation::right);
  EXPECT_EQ(parse_depth_location("2"), DepthLocation::right);
  EXPECT_EQ(parse_depth_location("left"), DepthLocation::left);
  EXPECT_EQ(parse_depth_location("3"), DepthLocation::left);
  for (const auto loc : {DepthLocation::top, DepthLocation::bottom, DepthLocation::right,
                         DepthLocation::left})
    EXPECT_EQ(parse_depth_location(depth_location_name(loc)), loc);
  expect_one_line_naming(input_error_of([] { parse_depth_location("4"); }), "depth_loc");
  expect_one_line_naming(input_error_of([] { parse_depth_location("middle"); }), "depth_loc");
}

TEST(RgbdOptions, SetsEachOptionFromItsBridgeKeyOrDashedFlag) {
  RgbdOptions o;
  set_rgbd_option(o, "depth-loc", "left");
  set_rgbd_option(o, "depthiness", "2.5");
  set_rgbd_option(o, "focus", "-0.02");
  set_rgbd_option(o, "depth_inversion", "1");
  set_rgbd_option(o, "chroma-depth", "true");
  set_rgbd_option(o, "zoom", "1.25");
  set_rgbd_option(o, "crop_pos_x", "0.5");
  set_rgbd_option(o, "crop-pos-y", "-1");
  set_rgbd_option(o, "depth-cutoff", "0.9");
  EXPECT_DOUBLE_EQ(o.depth_cutoff, 0.9);
  set_rgbd_option(o, "depth_cutoff", "true");  // bridge.js 0.0.8-alpha.4's flag: the range's ends
  EXPECT_DOUBLE_EQ(o.depth_cutoff, 1.0);
  set_rgbd_option(o, "depth_cutoff", "0");
  EXPECT_DOUBLE_EQ(o.depth_cutoff, 0.0);
  EXPECT_EQ(o.depth_loc, DepthLocation::left);
  EXPECT_DOUBLE_EQ(o.depthiness, 2.5);
  EXPECT_DOUBLE_EQ(o.focus, -0.02);
  EXPECT_TRUE(o.depth_inversion);
  EXPECT_TRUE(o.chroma_depth);
  EXPECT_DOUBLE_EQ(o.zoom, 1.25);
  EXPECT_DOUBLE_EQ(o.crop_pos_x, 0.5);
  EXPECT_DOUBLE_EQ(o.crop_pos_y, -1.0);
}

TEST(RgbdOptions, BadValuesAreOneLineErrorsNamingTheFieldAndLeaveTheOptionsAlone) {
  RgbdOptions o;
  const RgbdOptions before = o;
  const struct {
    const char* key;
    const char* value;
    const char* field;
  } cases[] = {
      {"depthiness", "0.05", "depthiness"}, {"depthiness", "5", "depthiness"},
      {"depthiness", "nan", "depthiness"},  {"depthiness", "1.5x", "depthiness"},
      {"focus", "0.2", "focus"},            {"focus", "", "focus"},
      {"zoom", "0", "zoom"},                {"zoom", "inf", "zoom"},
      {"crop_pos_x", "3", "crop_pos_x"},    {"crop_pos_y", "-2.5", "crop_pos_y"},
      {"depth_inversion", "2", "depth_inversion"}, {"chroma_depth", "maybe", "chroma_depth"},
      {"depth_loc", "5", "depth_loc"},      {"sharpness", "1", "sharpness"},
      {"depth_cutoff", "1.5", "depth_cutoff"}, {"depth_cutoff", "-0.1", "depth_cutoff"},
      {"depth_cutoff", "deep", "depth_cutoff"},
  };
  for (const auto& c : cases) {
    expect_one_line_naming(input_error_of([&] { set_rgbd_option(o, c.key, c.value); }), c.field);
    EXPECT_EQ(o.depthiness, before.depthiness);
    EXPECT_EQ(o.zoom, before.zoom);
    EXPECT_EQ(o.depth_loc, before.depth_loc);
  }
}

TEST(RgbdOptions, ReadsABridgeJsRgbdHologramsSettings) {
  // bridge.js README's RGBDHologram example (with the keys lfd leaves to its caller).
  const RgbdOptions o = parse_rgbd_options_json(
      R"({"depthiness": 2.0, "focus": 0, "aspect": 1, "chroma_depth": 0, "depth_inversion": 1,
          "depth_loc": 3, "depth_cutoff": 1, "zoom": 1, "uri": "rgbd.png"})");
  EXPECT_DOUBLE_EQ(o.depthiness, 2.0);
  EXPECT_EQ(o.depth_loc, DepthLocation::left);
  EXPECT_TRUE(o.depth_inversion);
  EXPECT_FALSE(o.chroma_depth);
  EXPECT_DOUBLE_EQ(o.depth_cutoff, 1.0);
  // Round trip through bridge.js's keys.
  RgbdOptions p;
  p.depth_loc = DepthLocation::bottom;
  p.focus = 0.03;
  p.chroma_depth = true;
  p.crop_pos_y = 0.5;
  p.depth_cutoff = 0.4;
  const RgbdOptions q = rgbd_options_from_json(rgbd_options_to_json(p));
  EXPECT_EQ(q.depth_loc, p.depth_loc);
  EXPECT_DOUBLE_EQ(q.focus, p.focus);
  EXPECT_EQ(q.chroma_depth, p.chroma_depth);
  EXPECT_DOUBLE_EQ(q.crop_pos_y, p.crop_pos_y);
  EXPECT_DOUBLE_EQ(q.depth_cutoff, p.depth_cutoff);
  EXPECT_DOUBLE_EQ(parse_rgbd_options_json(R"({"depth_cutoff": true})").depth_cutoff, 1.0);
  EXPECT_DOUBLE_EQ(parse_rgbd_options_json(R"({"depth_cutoff": 0.25})").depth_cutoff, 0.25);
  EXPECT_TRUE(parse_rgbd_options_json(R"({"chroma_depth": true})").chroma_depth);
}

TEST(RgbdOptions, BadJsonIsAOneLineErrorNamingTheKey) {
  const struct {
    const char* text;
    const char* field;
  } cases[] = {
      {"[1, 2]", "RGB-D settings"},          {"{\"depthiness\": ", "RGB-D settings"},
      {R"({"depthiness": "lots"})", "depthiness"}, {R"({"depthiness": 9})", "depthiness"},
      {R"({"depth_loc": 7})", "depth_loc"},  {R"({"depth_loc": 1.5})", "depth_loc"},
      {R"({"depth_loc": "sideways"})", "depth_loc"}, {R"({"chroma_depth": 2})", "chroma_depth"},
      {R"({"depth_inversion": "yes"})", "depth_inversion"}, {R"({"zoom": null})", "zoom"},
      {R"({"focus": -1})", "focus"},         {R"({"depth_cutoff": 2})", "depth_cutoff"},
      {R"({"depth_cutoff": "half"})", "depth_cutoff"},
  };
  for (const auto& c : cases)
    expect_one_line_naming(input_error_of([&] { parse_rgbd_options_json(c.text); }), c.field);
}

}  // namespace
}  // namespace lfd::rgbd
