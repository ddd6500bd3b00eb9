#include "play/transport.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::play {

double steady_clock_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double entry_run_time_s(const PlaylistEntry& entry, const OpenedEntry& opened, double image_duration_s) {
  return entry.duration_s.value_or(opened.video ? 0.0 : image_duration_s);
}

Transport::Transport(TransportOptions options, TransportOutput& output,
                     std::function<void(const PlaybackEvent&)> on_event, TransportClock clock)
    : options_(options), output_(output), on_event_(std::move(on_event)), clock_(std::move(clock)),
      looping_(options.loop) {}

PlaylistEntry* Transport::current_entry() {
  return index_ >= 0 && index_ < int(playlist_.size()) ? &playlist_[size_t(index_)] : nullptr;
}

double Transport::duration_s() const {
  if (!has_entry_) return 0;
  return run_s_ > 0 ? run_s_ : opened_.video ? opened_.video_length_s : 0;
}

void Transport::emit(PlaybackEventKind kind, const std::string& message, const std::string& name) {
  if (on_event_) on_event_(PlaybackEvent{kind, index_, name.empty() ? name_ : name, position_, message});
}

void Transport::close_entry() {
  output_.close();
  has_entry_ = false;
  name_.clear();
  opened_ = {};
  run_s_ = 0;
  started_ = false;
  position_ = 0;
}

void Transport::set_playlist(std::vector<PlaylistEntry> entries, int start) {
  close_entry();
  playlist_ = std::move(entries);
  index_ = -1;
  if (!playlist_.empty()) go_to(start);
}

void Transport::show_picture(const std::string& name) {
  close_entry();
  playlist_.clear();
  index_ = -1;
  has_entry_ = true;
  name_ = name;
  playing_ = true;
}

void Transport::go_to(int entry_index) {
  if (playlist_.empty()) return;
  const int n = int(playlist_.size());
  playing_ = true;  // before: a playlist whose every entry is bad ends, not playing
  start_entry(((entry_index % n) + n) % n);
}

// Entry `first`, else the ones after it (a notice and kEntrySkipped each; past the last only
// when looping); the playlist ends when none opens.
void Transport::start_entry(int first) {
  close_entry();
  const int n = int(playlist_.size());
  for (int tried = 0, i = first; tried < n; ++tried, i = (i + 1) % n) {
    if (i < first && !looping_ && tried > 0) break;
    const PlaylistEntry& entry = playlist_[size_t(i)];
    try {
      opened_ = output_.open(entry);
      index_ = i;
      has_entry_ = true;
      name_ = entry.path.filename().string();
      run_s_ = entry_run_time_s(entry, opened_, options_.image_duration_s);
      return;
    } catch (const InputError& e) {
      index_ = i;
      if (options_.print_notices) std::cerr << fmt::format("notice: skipped: {}\n", e.what());
      emit(PlaybackEventKind::kEntrySkipped, e.what(), entry.path.filename().string());
    }
  }
  end_playlist();
}

void Transport::end_playlist() {
  close_entry();
  playing_ = false;
  emit(PlaybackEventKind::kPlaylistEnded);
}

// The current entry ran its course: the next one, the first again when looping, or the end.
void Transport::advance() {
  emit(PlaybackEventKind::kEntryEnded);
  if (index_ < 0) {  // a picture from show_picture has no successor
    close_entry();
    return;
  }
  const bool last = index_ + 1 >= int(playlist_.size());
  if (last && !looping_) return end_playlist();
  if (last) emit(PlaybackEventKind::kLoopRestarted);
  if (last && playlist_.size() == 1 && has_entry_ && opened_.video) {  // one looping video: rewind it
    output_.seek(0);
    position_ = 0;
    return;
  }
  start_entry(last ? 0 : index_ + 1);
}

void Transport::seek(double seconds) {
  if (!has_entry_) return;
  double end = run_s_;
  if (opened_.video && opened_.video_length_s > 0)
    end = end > 0 ? std::min(end, opened_.video_length_s) : opened_.video_length_s;
  position_ = std::max(seconds, 0.0);
  if (end > 0) position_ = std::min(position_, end);
  if (opened_.video) output_.seek(position_);
  emit(PlaybackEventKind::kSeeked);
}

void Transport::set_playing(bool on) {
  if (on == playing_) return;
  playing_ = on;
  emit(on ? PlaybackEventKind::kResumed : PlaybackEventKind::kPaused);
}

void Transport::quit() {
  if (quit_) return;
  quit_ = true;
  emit(PlaybackEventKind::kQuit);
}

// The clock: the time between ticks while playing (a stalled frame counts as long as it took).
void Transport::tick() {
  const double now = clock_();
  const double dt = last_tick_s_ ? now - *last_tick_s_ : 0.0;
  last_tick_s_ = now;
  if (playing_ && has_entry_ && started_) position_ += dt;
}

void Transport::first_frame_at(double pts_s) {
  if (!started_) position_ = pts_s;
}

void Transport::picture_shown() {
  if (!has_entry_ || started_) return;
  started_ = true;
  emit(PlaybackEventKind::kEntryStarted);
}

void Transport::end_if_due(bool media_ended) {
  if (!has_entry_) return;
  if (media_ended || (run_s_ > 0 && position_ >= run_s_)) advance();
}

void Transport::skip_rest(const std::string& message) {
  emit(PlaybackEventKind::kEntrySkipped, message);
  advance();
}

void Transport::report_skipped(const std::string& message) { emit(PlaybackEventKind::kEntrySkipped, message); }

}  // namespace lfd::play
