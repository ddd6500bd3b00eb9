// The Player's commands from another thread (what `lfd serve` does from its network threads):
// queued and applied on the GL thread in order, with the events and the state to match.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "media/synthetic_quilt.hpp"
#include "play/player.hpp"
#include "render/image_metrics.hpp"
#include "tests/rgbd/rgbd_fixture.hpp"
#include "util/error.hpp"

namespace lfd::play {
namespace {

namespace fs = std::filesystem;

fs::path write_quilt(const std::string& stem, int frame) {
  render::QuiltLayout q;
  q.cols = 8;
  q.rows = 6;
  q.views = 48;
  q.aspect = 0.75;
  q.width = 8 * 48;
  q.height = 6 * 64;
  const fs::path dir = fs::temp_directory_path() / "lfd_player_threads_test";
  fs::create_directories(dir);
  const fs::path path = dir / (stem + render::quilt_suffix(q.cols, q.rows, q.aspect) + ".png");
  write_png(path, media::synthetic_quilt(q, frame));
  return path;
}

TEST(PlayerThreads, CommandsFromAnotherThreadApplyInOrder) {
  PlayerOptions options;
  options.calibration =
      display::read_calibration(fs::path(LFD_TEST_DATA_DIR) / "calibrations" / "LKG-PORT-portrait.visual.json");
  options.print_notices = false;
  Player player(options);
  std::mutex mutex;
  std::vector<std::pair<PlaybackEventKind, int>> events;
  player.subscribe([&](const PlaybackEvent& e) {
    std::lock_guard lock(mutex);
    events.emplace_back(e.kind, e.entry_index);
  });
  const std::vector<PlaylistEntry> entries = {{write_quilt("a", 0)}, {write_quilt("b", 1)}};
  std::atomic<bool> done = false;
  std::thread network([&] {
    player.set_playlist(entries);
    while (player.state().entry_index != 0 || player.state().frames_shown < 2) std::this_thread::yield();
    player.next();
    player.pause();
    player.seek(3);
    while (player.state().entry_index != 1 || player.state().playing) std::this_thread::yield();
    player.quit();
    done = true;
  });
  const int64_t frames = player.run(400);
  network.join();
  ASSERT_TRUE(done);
  EXPECT_LT(frames, 400);  // quit() ended the loop
  const PlayerState s = player.state();
  EXPECT_EQ(s.entry_index, 1);
  EXPECT_EQ(s.entry_count, 2);
  EXPECT_FALSE(s.playing);
  EXPECT_DOUBLE_EQ(s.position_s, 3.0);
  EXPECT_TRUE(s.quit);
  std::lock_guard lock(mutex);
  const std::vector<std::pair<PlaybackEventKind, int>> expected = {
      {PlaybackEventKind::kEntryStarted, 0}, {PlaybackEventKind::kPaused, 1}, {PlaybackEventKind::kSeeked, 1},
      {PlaybackEventKind::kEntryStarted, 1}, {PlaybackEventKind::kQuit, 1}};
  EXPECT_EQ(events, expected);
}

// Bridge's update_current_entry through lfd serve: an RGB-D setting changed on the entry shown
// makes its views again, equal to an entry that had the setting from the start.
TEST(PlayerThreads, RgbdSettingOfTheShownEntryChangesItsViews) {
  PlayerOptions options;
  options.calibration =
      display::read_calibration(fs::path(LFD_TEST_DATA_DIR) / "calibrations" / "LKG-PORT-portrait.visual.json");
  options.print_notices = false;
  Player player(options);
  const fs::path dir = fs::temp_directory_path() / "lfd_player_threads_test";
  fs::create_directories(dir);
  const fs::path frame = dir / "layers_rgbd.png";
  write_png(frame, to_uint8(rgbd::test::layered_rgbd_frame(160, 120, rgbd::DepthLocation::right)));
  rgbd::RgbdOptions deep, flat;
  deep.depthiness = 2.0;
  flat.depthiness = 0.1;
  PlaylistEntry a{frame}, b{frame};
  a.rgbd = deep;
  b.rgbd = flat;
  player.set_playlist({a, b});
  player.pause();
  Image8 before, after, reference;
  player.run(3, &before);
  EXPECT_THROW(player.update_rgbd_option("depthiness", "99"), InputError);  // out of bridge.js's range
  EXPECT_THROW(player.update_rgbd_option("depth_loc", "left"), InputError);  // would change the layout
  player.update_rgbd_option("depthiness", "0.1");
  player.run(2, &after);
  player.go_to(1);
  player.run(2, &reference);
  EXPECT_EQ(player.state().entry_index, 1);
  EXPECT_GE(render::psnr(to_float(after), to_float(reference)), 40.0);
  EXPECT_LT(render::psnr(to_float(before), to_float(reference)), 35.0);
}

}  // namespace
}  // namespace lfd::play
