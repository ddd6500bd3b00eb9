// Playlist JSON: the entries and their fields as written, relative files against the playlist's
// folder, and every malformed field refused naming the file and the field.
#include <gtest/gtest.h>

#include "play/playlist.hpp"
#include "util/error.hpp"

namespace lfd::play {
namespace {

TEST(Playlist, ReadsEntriesAndFields) {
  const Playlist p = parse_playlist_json(
      R"({"loop": false, "entries": [{"file": "a_qs5x9a1.6.png", "duration": 8},
          {"file": "/abs/clip.mp4", "cols": 8, "rows": 6, "views": 45, "aspect": 0.75}]})",
      "list.json", "/base");
  ASSERT_EQ(p.entries.size(), 2u);
  EXPECT_EQ(p.loop, false);
  EXPECT_EQ(p.entries[0].path, "/base/a_qs5x9a1.6.png");
  EXPECT_EQ(p.entries[0].duration_s, 8.0);
  EXPECT_FALSE(p.entries[0].quilt.cols);
  EXPECT_EQ(p.entries[1].path, "/abs/clip.mp4");
  EXPECT_EQ(p.entries[1].quilt.cols, 8);
  EXPECT_EQ(p.entries[1].quilt.rows, 6);
  EXPECT_EQ(p.entries[1].quilt.views, 45);
  EXPECT_EQ(p.entries[1].quilt.aspect, 0.75);
  EXPECT_FALSE(p.entries[1].duration_s);
  const Playlist bare = parse_playlist_json(R"([{"file": "x.png"}])", "bare.json", "");
  EXPECT_EQ(bare.entries.size(), 1u);
  EXPECT_FALSE(bare.loop);
}

TEST(Playlist, RgbdEntriesTakeBridgeJsSettings) {
  const Playlist p = parse_playlist_json(
      R"([{"file": "a.jpg", "rgbd": {"depth_loc": 3, "depthiness": 2, "depth_inversion": 1}},
          {"file": "b.jpg", "rgbd": true}, {"file": "c_qs5x9a1.6.png"}])",
      "list.json", "/");
  ASSERT_EQ(p.entries.size(), 3u);
  ASSERT_TRUE(p.entries[0].rgbd);
  EXPECT_EQ(p.entries[0].rgbd->depth_loc, rgbd::DepthLocation::left);
  EXPECT_EQ(p.entries[0].rgbd->depthiness, 2.0);
  EXPECT_TRUE(p.entries[0].rgbd->depth_inversion);
  ASSERT_TRUE(p.entries[1].rgbd);
  EXPECT_EQ(p.entries[1].rgbd->depthiness, rgbd::kDefaultDepthiness);
  EXPECT_FALSE(p.entries[2].rgbd);
}

TEST(Playlist, MalformedFieldsAreNamed) {
  const std::vector<std::pair<const char*, const char*>> cases = {
      {"not json", "not valid JSON"},
      {R"({"entries": []})", "entries: empty"},
      {R"({"entries": {}})", "entries: must be an array"},
      {R"({"entrys": []})", "entrys: unknown field"},
      {R"({"loop": 1, "entries": [{"file": "a"}]})", "loop: must be true or false"},
      {R"([{"duration": 3}])", "entries[0].file: missing"},
      {R"([{"file": "a", "duration": -1}])", "entries[0].duration"},
      {R"([{"file": "a", "duration": "5"}])", "entries[0].duration: must be a number"},
      {R"([{"file": "a"}, {"file": "b", "cols": 0}])", "entries[1].cols"},
      {R"([{"file": "a", "rows": 1e9}])", "entries[0].rows"},
      {R"([{"file": "a", "aspect": 0}])", "entries[0].aspect"},
      {R"([{"file": "a", "colz": 5}])", "entries[0].colz: unknown field"},
      {R"([{"file": ""}])", "entries[0].file: must be a file name"},
      {R"([3])", "entries[0]: must be an object"},
      {R"([{"file": "a", "rgbd": false}])", "entries[0].rgbd: must be true or an object"},
      {R"([{"file": "a", "rgbd": {"depthiness": 9}}])", "entries[0].rgbd: "},
  };
  for (const auto& [text, expected] : cases) {
    try {
      parse_playlist_json(text, "list.json", "/");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << text << " -> " << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("list.json", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace lfd::play
