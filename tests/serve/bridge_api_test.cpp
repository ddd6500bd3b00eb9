// Bridge's HTTP API against the test double: replies in {name, type, value} shape, playlists
// from checked files, transport, events, and refusals that change nothing.
#include <sys/stat.h>

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
  // A studio playlist file named by the request is not read.
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

TEST_F(BridgeApiTest, GarbageGetsAnErrorReply) {
  EXPECT_EQ(api.handle("instance_playlist", "{not json").http_status, 400);
  EXPECT_EQ(api.handle("instance_playlist", "[1,2]").http_status, 400);
  EXPECT_EQ(api.handle("instance_playlist", std::string(100000, '[')).http_status, 400);
  EXPECT_EQ(api.handle("no_such_endpoint", "{}").http_status, 404);
  EXPECT_EQ(api.handle("instance_playlist", std::string(limits.max_body_bytes + 1, ' ')).http_status, 400);
  EXPECT_EQ(playlists.size(), 0u);
}

}  // namespace
}  // namespace lfd::serve
