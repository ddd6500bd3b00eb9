// Bridge's HTTP API against the test double: replies in {name, type, value} shape, playlists
// from checked files, transport, events, and refusals that change nothing.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "serve/bridge_api.hpp"
#include "tests/serve/fake_display_service.hpp"
#include "tests/serve/serve_test_support.hpp"

namespace lfd::serve {
namespace {

using json = nlohmann::json;

struct BridgeApiTest : ::testing::Test {
  ServeLimits limits;
  test::TempDir tmp;
  test::FakeDisplayService fake{{test::fixture_display()}};
  PlaylistStore playlists{tmp.path / "state" / "playlists.json", limits};
  EventHub hub;
  std::vector<json> events;
  BridgeApi api{fake, playlists, hub, limits};
  std::string token;

  void SetUp() override {
    hub.subscribe([this](const std::string& t) { events.push_back(json::parse(t)); });
    token = call("enter_orchestration", {{"name", "default"}})["payload"]["value"];
  }
  json call(const std::string& endpoint, json body, int expect_status = 200) {
    const BridgeResponse r = api.handle(endpoint, body.dump());
    EXPECT_EQ(r.http_status, expect_status) << endpoint << ": " << r.body;
    return json::parse(r.body);
  }
  // A Looking Glass Studio playlist folder (docs/serve.md "Studio playlists"): playlist.json,
  // a quilt and an RGB-D image, each with its sidecar settings.
  std::filesystem::path studio_playlist(const json& items = json::array({"quilt_qs4x3.png", "photo_rgbd.png"})) {
    const auto dir = tmp.path / "HoloPlay Studio" / "Playlists";
    std::filesystem::create_directories(dir);
    write_png(dir / "quilt_qs4x3.png", test::pattern_quilt(40, 36));
    write_png(dir / "photo_rgbd.png", test::pattern_quilt(64, 32));
    write_text(dir / "quilt_qs4x3.png.json",
               R"({"movie": false, "mediaType": "quilt", "quilt_settings": {"viewX": 4, "viewY": 3,
                   "viewTotal": 12, "aspect": 0.75, "invertViews": false}, "focus": 0.0, "zoom": 1,
                   "duration": 10.0})");
    write_text(dir / "photo_rgbd.png.json",
               R"({"movie": false, "mediaType": "rgbd", "depthiness": 2.5, "depthInversion": true,
                   "chromaDepth": false, "depthPosition": "left", "focus": 0.01, "zoom": 1.5,
                   "position_x": 0.5, "position_y": -0.25, "viewOrderReversed": false, "duration": 4.5})");
    json list = json::array();
    for (const auto& name : items) list.push_back({{"filename", name}, {"last_updated", "2024-05-01"}, {"needs_sync", false}});
    write_text(dir / "playlist.json", list.dump());
    return dir / "playlist.json";
  }
  static void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file) << text;
  }
  std::string quilt_file() {
    const auto file = tmp.path / "hologram_qs4x3a0.75.png";
    write_png(file, test::pattern_quilt(40, 36));
    return "file://" + file.string();
  }
};

TEST_F(BridgeApiTest, VersionAndOrchestrationInBridgesShape) {
  const json v = call("bridge_version", json::object());
  EXPECT_EQ(v["payload"]["type"], "WSTRING");
  EXPECT_EQ(v["payload"]["value"], kBridgeApiVersion);
  EXPECT_EQ(v["status"]["value"], "Completion");
  EXPECT_EQ(token.size(), 32u);
}

TEST_F(BridgeApiTest, AvailableOutputDevicesCarriesTheCalibrationAsJsonText) {
  const json r = call("available_output_devices", {{"orchestration", token}});
  const json& d = r["payload"]["value"]["0"]["value"];
  EXPECT_NE(d["hwid"]["value"].get<std::string>().find("LKG"), std::string::npos);
  const json cal = json::parse(d["calibration"]["value"].get<std::string>());
  EXPECT_DOUBLE_EQ(cal["pitch"]["value"].get<double>(), test::fixture_display().calibration.display.pitch_lpi);
  const json quilt = json::parse(d["defaultQuilt"]["value"].get<std::string>());
  EXPECT_EQ(quilt["tileX"], test::fixture_display().default_quilt.cols);
  EXPECT_EQ(d["windowCoords"]["type"], "INT2");
}

TEST_F(BridgeApiTest, AnUnknownOrchestrationChangesNothing) {
  const json r = call("transport_control_play", {{"orchestration", "not-a-token"}});
  EXPECT_EQ(r["status"]["value"], "UnknownOrchestration");
  EXPECT_TRUE(fake.recorded().empty());
}

TEST_F(BridgeApiTest, UpdatePlaylistEntryChangesOnlyTheFieldsGivenAndReplaysThePlaylistShown) {
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}, {"loop", true}});
  call("insert_playlist_entry", {{"orchestration", token}, {"name", "p"}, {"index", 0}, {"uri", quilt_file()},
                                 {"rows", 3}, {"cols", 4}, {"aspect", 0.75}, {"view_count", 12}});
  call("play_playlist", {{"orchestration", token}, {"name", "p"}, {"head_index", -1}});
  fake.state_playlist = "p";
  call("update_playlist_entry", {{"orchestration", token}, {"playlistName", "p"}, {"playlistIndex", 0},
                                 {"focus", "0.5"}, {"aspect", 0.8}});
  const auto stored = playlists.get("p");
  ASSERT_TRUE(stored);
  EXPECT_DOUBLE_EQ(stored->entries[0].focus, 0.5);
  EXPECT_DOUBLE_EQ(stored->entries[0].quilt.aspect, 0.8);
  EXPECT_EQ(stored->entries[0].quilt.views, 12);  // kept
  EXPECT_EQ(fake.last_playlist.entries[0].focus, 0.5);  // the playlist shown plays with the change
  const json bad = call("update_playlist_entry", {{"orchestration", token}, {"playlistName", "p"}, {"playlistIndex", 3}}, 400);
  EXPECT_NE(bad["payload"]["value"].get<std::string>().find("playlistIndex: 3"), std::string::npos);
  EXPECT_DOUBLE_EQ(playlists.get("p")->entries[0].focus, 0.5);
}

TEST_F(BridgeApiTest, AutostartPlaylistIsKeptInTheStateFile) {
  EXPECT_EQ(call("get_autostart_playlist", {{"orchestration", token}, {"head_index", -1}})["payload"]["value"]
                ["playlist_name"]["value"], "");
  call("set_named_autostart_playlist", {{"orchestration", token}, {"playlist_name", "missing"}, {"head_index", -1}}, 400);
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}, {"loop", true}});
  const json set = call("set_named_autostart_playlist", {{"orchestration", token}, {"playlist_name", "p"}, {"head_index", 2}});
  EXPECT_EQ(set["payload"]["value"]["playlist_name"]["value"], "p");
  const json got = call("get_autostart_playlist", {{"orchestration", token}, {"head_index", -1}});
  EXPECT_EQ(got["payload"]["value"]["playlist_name"]["value"], "p");
  EXPECT_EQ(got["payload"]["value"]["playlist_path"]["type"], "WSTRING");
  // A file that is not a Studio playlist is refused and changes nothing.
  call("set_autostart_playlist", {{"orchestration", token}, {"playlist_name", "p"}, {"playlist_path", "/etc/passwd"},
                                  {"head_index", -1}}, 400);
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.autostart());
  EXPECT_EQ(again.autostart()->name, "p");
  EXPECT_EQ(again.autostart()->head_index, 2);
}

TEST_F(BridgeApiTest, PlaysAPlaylistOfCheckedFiles) {
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}, {"loop", true}});
  call("insert_playlist_entry", {{"orchestration", token}, {"name", "p"}, {"index", 0}, {"uri", quilt_file()},
                                 {"rows", 3}, {"cols", 4}, {"aspect", 0.75}, {"view_count", 12}, {"isRGBD", 0}});
  call("play_playlist", {{"orchestration", token}, {"name", "p"}, {"head_index", -1}});
  ASSERT_EQ(fake.last_playlist.entries.size(), 1u);
  EXPECT_EQ(fake.last_playlist.entries[0].quilt.views, 12);
  EXPECT_EQ(fake.recorded().back(), "play_playlist 0 p -1");
  EXPECT_EQ(events.back()["payload"]["value"]["event"]["value"], "Sync/Play Playlist");
  // Kept for a restart: a second store reads the state file back.
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.get("p"));
  EXPECT_EQ(again.get("p")->entries[0].file, fake.last_playlist.entries[0].file);
}

TEST_F(BridgeApiTest, RgbdEntriesCarryBridgeJsSettingsToThePlayer) {
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}});
  call("insert_playlist_entry", {{"orchestration", token}, {"name", "p"}, {"index", 0}, {"uri", quilt_file()},
                                 {"isRGBD", 1}, {"depth_loc", 3}, {"depthiness", "2.5"}, {"focus", 0.01},
                                 {"depth_inversion", 1}, {"chroma_depth", 0}, {"zoom", 1.5}});
  call("insert_playlist_entry", {{"orchestration", token}, {"name", "p"}, {"index", 1}, {"uri", quilt_file()},
                                 {"rows", 1}, {"cols", 1}, {"isRGBD", 0}});
  call("play_playlist", {{"orchestration", token}, {"name", "p"}, {"head_index", -1}});
  ASSERT_EQ(fake.last_playlist.entries.size(), 2u);
  const auto& rgbd = fake.last_playlist.entries[0].rgbd;
  ASSERT_TRUE(rgbd);
  EXPECT_EQ(rgbd->depth_loc, rgbd::DepthLocation::left);
  EXPECT_DOUBLE_EQ(rgbd->depthiness, 2.5);
  EXPECT_DOUBLE_EQ(rgbd->focus, 0.01);
  EXPECT_TRUE(rgbd->depth_inversion);
  EXPECT_DOUBLE_EQ(rgbd->zoom, 1.5);
  EXPECT_FALSE(fake.last_playlist.entries[1].rgbd);
  // The state file keeps them: a second store reads the same settings back.
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.get("p"));
  ASSERT_TRUE(again.get("p")->entries[0].rgbd);
  EXPECT_DOUBLE_EQ(again.get("p")->entries[0].rgbd->depthiness, 2.5);
  EXPECT_FALSE(again.get("p")->entries[1].rgbd);
  // Out of bridge.js's range: an error reply naming the key, and the playlist unchanged.
  const BridgeResponse bad = api.handle("insert_playlist_entry",
      json{{"orchestration", token}, {"name", "p"}, {"uri", quilt_file()}, {"isRGBD", 1}, {"depthiness", 99}}.dump());
  EXPECT_EQ(bad.http_status, 400);
  EXPECT_NE(bad.body.find("depthiness"), std::string::npos) << bad.body;
  EXPECT_EQ(playlists.get("p")->entries.size(), 2u);
}

TEST_F(BridgeApiTest, RefusesUrisThatAreNotReadableRegularFiles) {
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}});
  const auto fifo = tmp.path / "fifo.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  limits.max_file_bytes = 100;
  const auto large = tmp.path / "large.png";
  write_png(large, test::pattern_quilt(64, 64));
  for (const std::string& uri : std::vector<std::string>{"http://example.com/q.png", "/etc", "file:///nonexistent/q.png", "relative.png",
                                "/proc/self/environ", fifo.string(), large.string(), "file://" + large.string()}) {
    const BridgeResponse r = api.handle("insert_playlist_entry",
        json{{"orchestration", token}, {"name", "p"}, {"uri", uri}, {"rows", 1}, {"cols", 1}}.dump());
    EXPECT_EQ(r.http_status, 400) << uri;
  }
  EXPECT_TRUE(playlists.get("p")->entries.empty());
}

TEST_F(BridgeApiTest, TransportAndCurrentEntryReachTheDisplay) {
  call("transport_control_pause", {{"orchestration", token}});
  call("transport_control_seek_to_index", {{"orchestration", token}, {"index", 2}});
  call("update_current_entry", {{"orchestration", token}, {"name", "p"}, {"focus", "0.25"}});
  const auto calls = fake.recorded();
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_EQ(calls[0], "transport 1 -1");
  EXPECT_EQ(calls[1], "transport 4 2");
  EXPECT_EQ(calls[2], "update focus 0.250000");
  EXPECT_EQ(events[0]["payload"]["value"]["event"]["value"], "Transport Control Pause");
}

TEST_F(BridgeApiTest, SeekWithinTheEntryReachesTheDisplayAndBadSecondsChangeNothing) {
  call("lfd_seek", {{"orchestration", token}, {"seconds", 12.5}});
  call("lfd_seek", {{"orchestration", token}, {"seconds", "3"}});  // numeric text, as bridge.js sends numbers
  call("lfd_seek", {{"orchestration", token}}, 400);
  call("lfd_seek", {{"orchestration", token}, {"seconds", -1}}, 400);
  call("lfd_seek", {{"orchestration", token}, {"seconds", "soon"}}, 400);
  EXPECT_EQ(json::parse(api.handle("lfd_seek", R"({"seconds": 1})").body)["status"]["value"], "UnknownOrchestration");
  const auto calls = fake.recorded();
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0], "seek 12.500000");
  EXPECT_EQ(calls[1], "seek 3.000000");
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0]["payload"]["value"]["event"]["value"], "lfd Transport Seek");
  const json status = call("lfd_status", json::object())["payload"]["value"];
  EXPECT_TRUE(status.contains("position_s") && status.contains("duration_s") && status.contains("is_video"));
}

TEST_F(BridgeApiTest, GarbageGetsAnErrorReply) {
  EXPECT_EQ(api.handle("instance_playlist", "{not json").http_status, 400);
  EXPECT_EQ(api.handle("instance_playlist", "[1,2]").http_status, 400);
  EXPECT_EQ(api.handle("instance_playlist", std::string(100000, '[')).http_status, 400);
  EXPECT_EQ(api.handle("no_such_endpoint", "{}").http_status, 404);
  EXPECT_EQ(api.handle("instance_playlist", std::string(limits.max_body_bytes + 1, ' ')).http_status, 400);
  EXPECT_EQ(playlists.size(), 0u);
}

TEST_F(BridgeApiTest, PlaysALookingGlassStudioPlaylistAsBridgeJsSendsIt) {
  // bridge.js's playStudioPlaylist: instance_studio_playlist, then play_playlist of its name.
  const auto path = studio_playlist();
  const json r = call("instance_studio_playlist", {{"orchestration", token}, {"name", "Studio Playlist"},
                                                   {"playlist_path", path.string()}, {"loop", true}});
  EXPECT_EQ(r["payload"]["value"]["name"]["value"], "Studio Playlist");
  call("play_playlist", {{"orchestration", token}, {"name", "Studio Playlist"}, {"head_index", -1}});
  ASSERT_EQ(fake.last_playlist.entries.size(), 2u);
  const PlaylistEntry& quilt = fake.last_playlist.entries[0];
  EXPECT_EQ(quilt.file, path.parent_path() / "quilt_qs4x3.png");
  EXPECT_EQ(quilt.quilt.cols, 4);
  EXPECT_EQ(quilt.quilt.rows, 3);
  EXPECT_EQ(quilt.quilt.views, 12);
  EXPECT_DOUBLE_EQ(quilt.quilt.aspect, 0.75);
  EXPECT_EQ(quilt.duration_ms, 10000);
  EXPECT_FALSE(quilt.rgbd);
  const PlaylistEntry& photo = fake.last_playlist.entries[1];
  ASSERT_TRUE(photo.rgbd);
  EXPECT_EQ(photo.rgbd->depth_loc, rgbd::DepthLocation::left);
  EXPECT_DOUBLE_EQ(photo.rgbd->depthiness, 2.5);
  EXPECT_TRUE(photo.rgbd->depth_inversion);
  EXPECT_FALSE(photo.rgbd->chroma_depth);
  EXPECT_DOUBLE_EQ(photo.rgbd->focus, 0.01);
  EXPECT_DOUBLE_EQ(photo.rgbd->zoom, 1.5);
  EXPECT_DOUBLE_EQ(photo.rgbd->crop_pos_x, 0.5);
  EXPECT_DOUBLE_EQ(photo.rgbd->crop_pos_y, -0.25);
  EXPECT_EQ(photo.duration_ms, 4500);
  // As a file:// URI too, and kept for a restart.
  call("instance_studio_playlist", {{"orchestration", token}, {"name", "again"},
                                    {"playlist_path", "file://" + path.string()}, {"loop", false}});
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.get("again"));
  EXPECT_EQ(again.get("again")->entries.size(), 2u);
  EXPECT_FALSE(again.get("again")->loop);
}

TEST_F(BridgeApiTest, ABadStudioPlaylistIsRefusedNamingTheFileAndChangesNothing) {
  const auto path = studio_playlist();
  call("instance_studio_playlist", {{"orchestration", token}, {"name", "Studio Playlist"}, {"playlist_path", path.string()}});
  const auto dir = path.parent_path();
  write_text(dir / "odd.png.json", R"({"mediaType": "lightfield"})");
  write_png(dir / "odd.png", test::pattern_quilt(40, 36));
  write_png(dir / "flipped.png", test::pattern_quilt(40, 36));
  write_text(dir / "flipped.png.json", R"({"mediaType": "quilt", "quilt_settings": {"viewX": 4, "viewY": 3, "invertViews": true}})");
  write_png(dir / "nosidecar.png", test::pattern_quilt(40, 36));
  const struct {
    json items;
    const char* says;
  } cases[] = {
      {json::array({"../escape.png"}), "leaves the playlist's folder"},
      {json::array({"/etc/passwd"}), "not relative"},
      {json::array({"missing.png"}), "missing.png.json"},
      {json::array({"nosidecar.png"}), "nosidecar.png.json"},
      {json::array({"odd.png"}), "mediaType"},
      {json::array({"flipped.png"}), "invertViews"},
  };
  for (const auto& c : cases) {
    const auto bad = studio_playlist(c.items);
    const json r = call("instance_studio_playlist", {{"orchestration", token}, {"name", "Studio Playlist"},
                                                     {"playlist_path", bad.string()}}, 400);
    const std::string message = r["payload"]["value"];
    EXPECT_NE(message.find(c.says), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(playlists.get("Studio Playlist")->entries.size(), 2u) << message;  // the first one stays
  }
  write_text(path, R"({"items": []})");
  call("instance_studio_playlist", {{"orchestration", token}, {"name", "x"}, {"playlist_path", path.string()}}, 400);
  call("instance_studio_playlist", {{"orchestration", token}, {"name", "x"}, {"playlist_path", "relative/playlist.json"}}, 400);
  call("instance_studio_playlist", {{"orchestration", token}, {"name", "x"}, {"playlist_path", "/proc/self/status"}}, 400);
  EXPECT_FALSE(playlists.get("x"));
}

TEST_F(BridgeApiTest, SetAutostartPlaylistReadsAStudioPlaylistFile) {
  const auto path = studio_playlist();
  call("set_autostart_playlist", {{"orchestration", token}, {"playlist_name", "studio"},
                                  {"playlist_path", path.string()}, {"head_index", -1}});
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.autostart());
  EXPECT_EQ(again.autostart()->name, "studio");
  ASSERT_TRUE(again.get("studio"));
  EXPECT_EQ(again.get("studio")->entries.size(), 2u);
}

TEST_F(BridgeApiTest, SyncOverwritePlaylistMakesItTheOneTheDisplayPlaysOnItsOwn) {
  call("instance_playlist", {{"orchestration", token}, {"name", "p"}, {"loop", true}});
  call("insert_playlist_entry", {{"orchestration", token}, {"name", "p"}, {"index", 0}, {"uri", quilt_file()},
                                 {"rows", 3}, {"cols", 4}, {"aspect", 0.75}, {"view_count", 12}});
  // The request of the vendor's Toolkit (LKG-Toolkit's TrySyncPlaylist).
  const json sync = {{"orchestration", token}, {"name", "p"}, {"head_index", -1}, {"crf", 20},
                     {"pixel_format", "yuv420p"}, {"encoder", "h265"}};
  json bad = sync;
  bad["name"] = "missing";
  call("sync_overwrite_playlist", bad, 400);
  bad = sync;
  bad["crf"] = 99;
  call("sync_overwrite_playlist", bad, 400);
  EXPECT_FALSE(playlists.autostart());
  EXPECT_TRUE(fake.recorded().empty());
  const json r = call("sync_overwrite_playlist", sync);
  EXPECT_EQ(r["payload"]["value"]["name"]["value"], "p");
  EXPECT_EQ(fake.recorded().back(), "play_playlist 0 p -1");
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[events.size() - 2]["payload"]["value"]["event"]["value"], "Sync/Play Playlist");
  EXPECT_EQ(events.back()["payload"]["value"]["event"]["value"], "Sync/Play Playlist Complete");
  PlaylistStore again{tmp.path / "state" / "playlists.json", limits};
  ASSERT_TRUE(again.autostart());
  EXPECT_EQ(again.autostart()->name, "p");
}

}  // namespace
}  // namespace lfd::serve
