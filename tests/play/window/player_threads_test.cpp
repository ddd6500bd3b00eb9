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

}  // namespace
}  // namespace lfd::play
