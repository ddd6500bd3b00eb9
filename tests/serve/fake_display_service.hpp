#pragma once
// A test double of serve::DisplayService (unit tests only; `lfd serve` runs on the Player):
// serves the displays it is given and records every call, so a test can check what a request
// changed, and that a refused one changed nothing.
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "serve/display_service.hpp"

namespace lfd::serve::test {

class FakeDisplayService : public DisplayService {
 public:
  explicit FakeDisplayService(std::vector<ServedDisplay> displays) : displays_(std::move(displays)) {}

  std::vector<ServedDisplay> displays() const override { return displays_; }
  void show_quilt(int display, const Image8& quilt, const QuiltSettings& settings, const std::string& label) override {
    std::lock_guard lock(mutex);
    calls.push_back("show_quilt " + std::to_string(display) + " " + label);
    last_quilt = quilt;
    last_settings = settings;
  }
  void wipe(int display) override { record("wipe " + std::to_string(display)); }
  void play_playlist(int display, const Playlist& playlist, int head) override {
    std::lock_guard lock(mutex);
    calls.push_back("play_playlist " + std::to_string(display) + " " + playlist.name + " " + std::to_string(head));
    last_playlist = playlist;
  }
  void stop_playlist(const std::string& name) override { record("stop_playlist " + name); }
  void transport(Transport command, int index) override {
    record("transport " + std::to_string(static_cast<int>(command)) + " " + std::to_string(index));
  }
  void seek(double seconds) override { record("seek " + std::to_string(seconds)); }
  void update_current_entry(const std::string& parameter, double value) override {
    record("update " + parameter + " " + std::to_string(value));
  }
  void show_window(bool show) override { record(std::string("show_window ") + (show ? "1" : "0")); }
  PlaybackState state() const override {
    std::lock_guard lock(mutex);
    PlaybackState s;
    s.showing = "a fake";
    s.playlist = state_playlist;
    return s;
  }
  std::optional<Image8> panel_picture(int display, std::chrono::milliseconds) override {
    record("panel_picture " + std::to_string(display));
    std::lock_guard lock(mutex);
    return panel;
  }
  void set_event_listener(std::function<void(const PlaybackEvent&)> listener) override {
    std::lock_guard lock(mutex);
    this->listener = std::move(listener);
  }

  std::vector<std::string> recorded() const {
    std::lock_guard lock(mutex);
    return calls;
  }

  mutable std::mutex mutex;
  std::vector<std::string> calls;
  Image8 last_quilt;
  QuiltSettings last_settings;
  Playlist last_playlist;
  std::string state_playlist;  // the playlist state() says is playing
  std::function<void(const PlaybackEvent&)> listener;
  std::optional<Image8> panel;  // what panel_picture() answers (none: the display gave nothing)

 private:
  void record(std::string call) {
    std::lock_guard lock(mutex);
    calls.push_back(std::move(call));
  }
  std::vector<ServedDisplay> displays_;
};

}  // namespace lfd::serve::test
