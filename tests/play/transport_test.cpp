// lfd play's transport (play/transport.hpp) on a fake clock and a fake output, no window and no
// GL: the playlist rules of docs/play.md "Playlists" and "Bad files" (skip a bad entry, loop,
// rewind a looping video, clamp a seek, each entry's duration, pause) and the events they send.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "play/transport.hpp"
#include "util/error.hpp"

namespace lfd::play {
namespace {

using Kind = PlaybackEventKind;

// Records what the transport asks of it. A file named bad* fails to open; a .mp4 is a video
// whose length is in `video_lengths_s` (4 s unless given).
struct FakeOutput : TransportOutput {
  std::vector<std::string> opened;  // every open asked for, the bad ones too
  std::vector<double> seeks;
  int closes = 0;
  std::map<std::string, double> video_lengths_s;

  OpenedEntry open(const PlaylistEntry& entry) override {
    const std::string name = entry.path.filename().string();
    opened.push_back(name);
    if (name.rfind("bad", 0) == 0) throw_input_error("{}: not a picture or video", name);
    if (entry.path.extension() != ".mp4") return {};
    const auto length = video_lengths_s.find(name);
    return {true, length == video_lengths_s.end() ? 4.0 : length->second};
  }
  void close() override { ++closes; }
  void seek(double seconds) override { seeks.push_back(seconds); }
};

PlaylistEntry entry(const std::string& file, std::optional<double> duration_s = std::nullopt) {
  PlaylistEntry e;
  e.path = file;
  e.duration_s = duration_s;
  return e;
}

std::vector<PlaylistEntry> entries(std::initializer_list<const char*> files) {
  std::vector<PlaylistEntry> out;
  for (const char* f : files) out.push_back(entry(f));
  return out;
}

class TransportTest : public ::testing::Test {
 protected:
  explicit TransportTest(TransportOptions options = {true, 2.0, false})
      : transport(options, output, [this](const PlaybackEvent& e) { events.push_back(e); },
                  [this] { return now_s; }) {}

  // One frame as the Player runs it: the clock, the end rule (`video_ended`: the output's video
  // ran out), the picture on screen.
  void frame(double dt_s, bool video_ended = false) {
    now_s += dt_s;
    transport.tick();
    transport.end_if_due(video_ended);
    transport.picture_shown();
  }
  // Frames of `dt_s` for `seconds` of the fake clock.
  void run_for(double seconds, double dt_s = 0.1) {
    for (double t = 0; t < seconds - 1e-9; t += dt_s) frame(dt_s);
  }

  std::vector<Kind> kinds() const {
    std::vector<Kind> out;
    for (const auto& e : events) out.push_back(e.kind);
    return out;
  }
  int count(Kind kind) const {
    return int(std::count_if(events.begin(), events.end(), [kind](const auto& e) { return e.kind == kind; }));
  }

  double now_s = 100;  // any origin: the transport only takes differences
  FakeOutput output;
  std::vector<PlaybackEvent> events;
  Transport transport;
};

class NoLoopTransportTest : public TransportTest {
 protected:
  NoLoopTransportTest() : TransportTest({false, 2.0, false}) {}
};

TEST_F(TransportTest, SkipsAnEntryThatFailsToOpenWithItsEventAndPlaysTheNext) {
  transport.set_playlist(entries({"a.png", "bad.png", "c.png"}));
  frame(0);
  ASSERT_EQ(transport.entry_name(), "a.png");
  run_for(2.2);  // a.png's 2 s run out
  EXPECT_EQ(output.opened, (std::vector<std::string>{"a.png", "bad.png", "c.png"}));
  EXPECT_EQ(transport.index(), 2);
  EXPECT_EQ(transport.entry_name(), "c.png");
  EXPECT_TRUE(transport.playing());  // skipped, not stopped
  ASSERT_EQ(count(Kind::kEntrySkipped), 1);
  const auto skipped = std::find_if(events.begin(), events.end(), [](const auto& e) { return e.kind == Kind::kEntrySkipped; });
  EXPECT_EQ(skipped->entry_index, 1);
  EXPECT_EQ(skipped->entry_name, "bad.png");
  EXPECT_NE(skipped->message.find("not a picture or video"), std::string::npos);
}

TEST_F(TransportTest, SkipsABadFirstEntryWhenThePlaylistStarts) {
  transport.set_playlist(entries({"bad.mp4", "b.png"}));
  EXPECT_EQ(transport.index(), 1);
  EXPECT_EQ(transport.entry_name(), "b.png");
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kEntrySkipped}));
}

TEST_F(TransportTest, APlaylistOfOnlyBadEntriesEndsWithEachSkipped) {
  transport.set_playlist(entries({"bad1.png", "bad2.mp4"}));
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kEntrySkipped, Kind::kEntrySkipped, Kind::kPlaylistEnded}));
  EXPECT_FALSE(transport.has_entry());
  EXPECT_FALSE(transport.playing());
  EXPECT_EQ(output.opened.size(), 2u);  // each tried once, not round and round
}

TEST_F(TransportTest, LoopsThePlaylistAfterItsLastEntry) {
  transport.set_playlist(entries({"a.png", "b.png"}));
  frame(0);
  run_for(4.5);  // both 2 s entries, and a little of the first again
  EXPECT_EQ(output.opened, (std::vector<std::string>{"a.png", "b.png", "a.png"}));
  EXPECT_EQ(transport.index(), 0);
  EXPECT_EQ(count(Kind::kLoopRestarted), 1);
  EXPECT_EQ(count(Kind::kEntryEnded), 2);
  EXPECT_EQ(count(Kind::kEntryStarted), 3);
  EXPECT_EQ(count(Kind::kPlaylistEnded), 0);
}

TEST_F(NoLoopTransportTest, WithoutLoopingThePlaylistEndsAfterItsLastEntry) {
  transport.set_playlist(entries({"a.png", "b.png"}));
  frame(0);
  run_for(4.5);
  EXPECT_EQ(output.opened, (std::vector<std::string>{"a.png", "b.png"}));
  EXPECT_EQ(count(Kind::kPlaylistEnded), 1);
  EXPECT_EQ(count(Kind::kLoopRestarted), 0);
  EXPECT_FALSE(transport.has_entry());
  EXPECT_FALSE(transport.playing());
}

TEST_F(NoLoopTransportTest, SetLoopTurnsLoopingOnForTheNextEnd) {
  transport.set_playlist(entries({"a.png"}));
  transport.set_loop(true);
  frame(0);
  run_for(2.2);
  EXPECT_EQ(count(Kind::kLoopRestarted), 1);
  EXPECT_TRUE(transport.has_entry());
}

TEST_F(TransportTest, RewindsALoopingVideoInsteadOfOpeningItAgain) {
  transport.set_playlist(entries({"clip.mp4"}));
  transport.first_frame_at(0);
  frame(0);
  run_for(3.0);
  frame(0.1, /*video_ended=*/true);
  EXPECT_EQ(output.opened, (std::vector<std::string>{"clip.mp4"}));
  EXPECT_EQ(output.seeks, (std::vector<double>{0.0}));
  EXPECT_DOUBLE_EQ(transport.position_s(), 0.0);
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kEntryStarted, Kind::kEntryEnded, Kind::kLoopRestarted}));
}

TEST_F(TransportTest, AVideoInALongerPlaylistIsOpenedAgainWhenTheLoopComesRound) {
  transport.set_playlist(entries({"clip.mp4", "a.png"}));
  frame(0);
  frame(0.1, /*video_ended=*/true);
  run_for(2.2);
  EXPECT_EQ(output.opened, (std::vector<std::string>{"clip.mp4", "a.png", "clip.mp4"}));
  EXPECT_TRUE(output.seeks.empty());
}

TEST_F(TransportTest, ClampsASeekToTheVideosLength) {
  output.video_lengths_s["clip.mp4"] = 4.0;
  transport.set_playlist(entries({"clip.mp4"}));
  transport.seek(10);
  EXPECT_DOUBLE_EQ(transport.position_s(), 4.0);
  transport.seek(-3);
  EXPECT_DOUBLE_EQ(transport.position_s(), 0.0);
  transport.seek(1.5);
  EXPECT_DOUBLE_EQ(transport.position_s(), 1.5);
  EXPECT_EQ(output.seeks, (std::vector<double>{4.0, 0.0, 1.5}));
  EXPECT_EQ(count(Kind::kSeeked), 3);
}

TEST_F(TransportTest, ClampsASeekToAVideosCutWhenShorterThanTheVideo) {
  transport.set_playlist({entry("clip.mp4", 3.0)});
  transport.seek(10);
  EXPECT_DOUBLE_EQ(transport.position_s(), 3.0);
}

TEST_F(TransportTest, ClampsASeekInAnImageToItsDurationWithoutSeekingTheOutput) {
  transport.set_playlist(entries({"a.png"}));
  transport.seek(5);
  EXPECT_DOUBLE_EQ(transport.position_s(), 2.0);
  EXPECT_TRUE(output.seeks.empty());
}

TEST_F(TransportTest, SeekByIsRelativeToThePosition) {
  transport.set_playlist(entries({"clip.mp4"}));
  frame(0);
  run_for(1.0);
  transport.seek_by(0.5);
  EXPECT_NEAR(transport.position_s(), 1.5, 1e-9);
  transport.seek_by(-5);
  EXPECT_DOUBLE_EQ(transport.position_s(), 0.0);
}

TEST_F(TransportTest, AnImageRunsTheDefaultDurationAndNoLonger) {
  transport.set_playlist(entries({"a.png", "b.png"}));
  EXPECT_DOUBLE_EQ(transport.duration_s(), 2.0);
  frame(0);
  run_for(1.9);
  EXPECT_EQ(transport.index(), 0);
  run_for(0.2);
  EXPECT_EQ(transport.index(), 1);
}

TEST_F(TransportTest, AnImageRunsItsEntrysDurationWhenGiven) {
  transport.set_playlist({entry("a.png", 0.5), entry("b.png")});
  EXPECT_DOUBLE_EQ(transport.duration_s(), 0.5);
  frame(0);
  run_for(0.4);
  EXPECT_EQ(transport.index(), 0);
  run_for(0.2);
  EXPECT_EQ(transport.index(), 1);
}

TEST_F(TransportTest, AVideoRunsToItsEndNotTheImageDuration) {
  output.video_lengths_s["clip.mp4"] = 30.0;
  transport.set_playlist(entries({"clip.mp4", "a.png"}));
  EXPECT_DOUBLE_EQ(transport.duration_s(), 30.0);
  frame(0);
  run_for(25);  // far past the image duration, before the video's end
  EXPECT_EQ(transport.index(), 0);
  frame(0.1, /*video_ended=*/true);
  EXPECT_EQ(transport.index(), 1);
}

TEST_F(TransportTest, AVideoIsCutAtItsEntrysDuration) {
  transport.set_playlist({entry("clip.mp4", 1.5), entry("a.png")});
  frame(0);
  run_for(1.4);
  EXPECT_EQ(transport.index(), 0);
  run_for(0.2);
  EXPECT_EQ(transport.index(), 1);
}

TEST(EntryRunTime, ImagesTakeTheDefaultVideosRunToTheirEnd) {
  EXPECT_DOUBLE_EQ(entry_run_time_s(entry("a.png"), {false, 0}, 7), 7.0);
  EXPECT_DOUBLE_EQ(entry_run_time_s(entry("a.png", 3.0), {false, 0}, 7), 3.0);
  EXPECT_DOUBLE_EQ(entry_run_time_s(entry("c.mp4"), {true, 12}, 7), 0.0);
  EXPECT_DOUBLE_EQ(entry_run_time_s(entry("c.mp4", 2.0), {true, 12}, 7), 2.0);
}

TEST_F(TransportTest, PauseStopsTheClockAndPlayStartsItAgain) {
  transport.set_playlist(entries({"a.png", "b.png"}));
  frame(0);
  run_for(1.0);
  const double at_pause = transport.position_s();
  transport.pause();
  transport.pause();  // already paused: no second event
  run_for(5.0);
  EXPECT_DOUBLE_EQ(transport.position_s(), at_pause);
  EXPECT_EQ(transport.index(), 0);  // a paused image does not run out
  transport.play();
  run_for(0.5);
  EXPECT_NEAR(transport.position_s(), at_pause + 0.5, 1e-9);
  EXPECT_EQ(count(Kind::kPaused), 1);
  EXPECT_EQ(count(Kind::kResumed), 1);
}

TEST_F(TransportTest, TogglePauseAlternates) {
  transport.set_playlist(entries({"a.png"}));
  transport.toggle_pause();
  EXPECT_FALSE(transport.playing());
  transport.toggle_pause();
  EXPECT_TRUE(transport.playing());
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kPaused, Kind::kResumed}));
}

TEST_F(TransportTest, TheClockStartsAtTheFirstFrameShown) {
  transport.set_playlist(entries({"clip.mp4"}));
  transport.tick();
  now_s += 3;  // opening and the first decode took 3 s
  transport.tick();
  EXPECT_DOUBLE_EQ(transport.position_s(), 0.0);
  transport.first_frame_at(0.04);
  transport.picture_shown();
  transport.first_frame_at(2.0);  // later frames do not move the clock
  EXPECT_DOUBLE_EQ(transport.position_s(), 0.04);
  now_s += 0.5;
  transport.tick();
  EXPECT_NEAR(transport.position_s(), 0.54, 1e-9);
}

TEST_F(TransportTest, NextAndPreviousWrapAroundAndResumePlaying) {
  transport.set_playlist(entries({"a.png", "b.png", "c.png"}));
  transport.pause();
  transport.previous();
  EXPECT_EQ(transport.index(), 2);
  EXPECT_TRUE(transport.playing());
  transport.next();
  EXPECT_EQ(transport.index(), 0);
  transport.go_to(4);
  EXPECT_EQ(transport.index(), 1);
  EXPECT_EQ(output.opened.size(), 4u);
}

TEST_F(TransportTest, AShownPictureStaysUntilTheNextCommand) {
  transport.set_playlist(entries({"a.png"}));
  transport.show_picture("from memory");
  frame(0);
  run_for(50);
  EXPECT_EQ(transport.index(), -1);
  EXPECT_EQ(transport.entry_count(), 0);
  EXPECT_EQ(transport.entry_name(), "from memory");
  EXPECT_EQ(count(Kind::kEntryEnded), 0);
  ASSERT_EQ(count(Kind::kEntryStarted), 1);
  EXPECT_EQ(events.back().entry_name, "from memory");
}

TEST_F(TransportTest, ACorruptVideoIsSkippedFromThereOn) {
  transport.set_playlist(entries({"clip.mp4", "a.png"}));
  frame(0);
  transport.skip_rest("clip.mp4: corrupt frame");
  EXPECT_EQ(transport.index(), 1);
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kEntryStarted, Kind::kEntrySkipped, Kind::kEntryEnded}));
  EXPECT_EQ(events[1].entry_name, "clip.mp4");
}

TEST_F(TransportTest, QuitIsSentOnce) {
  transport.quit();
  transport.quit();
  EXPECT_TRUE(transport.quitting());
  EXPECT_EQ(kinds(), (std::vector<Kind>{Kind::kQuit}));
}

TEST_F(TransportTest, EventsCarryTheEntryAndThePosition) {
  transport.set_playlist(entries({"a.png", "b.png"}));
  frame(0);
  run_for(1.0);
  transport.seek(1.25);
  ASSERT_EQ(events.back().kind, Kind::kSeeked);
  EXPECT_EQ(events.back().entry_index, 0);
  EXPECT_EQ(events.back().entry_name, "a.png");
  EXPECT_DOUBLE_EQ(events.back().position_s, 1.25);
}

}  // namespace
}  // namespace lfd::play
