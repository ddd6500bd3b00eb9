#pragma once
// DisplayService on `lfd play`'s Players (play/player.hpp), one per served display: what
// `lfd serve` runs. Quilts shown in memory, playlists of checked files, transport and events go
// through each Player's thread-safe command queue; the Players' frames run on the main thread
// (apps/serve.cpp). What the Player cannot do is refused with a message, never pretended
// (docs/serve.md). What each display holds (the picture shown, its texture, the one waiting or
// being decoded) is reserved from the service's budget, sized by the newest content; content
// that does not fit is busy (docs/serve.md, "Memory").
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "play/player.hpp"
#include "serve/display_service.hpp"
#include "serve/memory_budget.hpp"

namespace lfd::serve {

class PlayerDisplayService : public DisplayService {
 public:
  // `players[i]` shows `displays[i]`; both outlive this object.
  PlayerDisplayService(std::vector<play::Player*> players, std::vector<ServedDisplay> displays, MemoryBudget& budget);
  ~PlayerDisplayService() override;

  std::vector<ServedDisplay> displays() const override { return displays_; }
  void show_quilt(int display, const Image8& quilt, const QuiltSettings& settings, const std::string& label) override;
  void wipe(int display) override;
  void play_playlist(int display, const Playlist& playlist, int head_index) override;
  void stop_playlist(const std::string& name) override;
  void transport(Transport command, int index) override;
  void seek(double seconds) override;
  void update_current_entry(const std::string& parameter, double value) override;
  void show_window(bool show) override;
  PlaybackState state() const override;
  std::optional<Image8> panel_picture(int display, std::chrono::milliseconds wait) override;
  void set_event_listener(std::function<void(const PlaybackEvent&)> listener) override;

 private:
  play::Player& player(int display) const;
  // Resizes display `display`'s reservation to `bytes`, or BusyError (nothing changes then).
  void hold_for_display(int display, std::size_t bytes, const std::string& what);
  void on_player_event(int display, const play::PlaybackEvent& event);

  std::vector<play::Player*> players_;
  std::vector<ServedDisplay> displays_;
  std::vector<int> subscriptions_;
  mutable std::mutex mutex_;
  MemoryBudget& budget_;
  std::mutex hold_mutex_;
  std::vector<MemoryBudget::Reservation> held_;  // per display
  std::unique_ptr<std::mutex[]> handing_over_;   // per display: one picture copied at a time
  std::string playlist_;      // the playlist the first display plays, empty if none
  int playlist_display_ = 0;
  std::string showing_;       // what was last shown through the service
  std::map<int, std::string> shown_key_;  // per display: the still playlist set last (empty: other content)
  std::function<void(const PlaybackEvent&)> listener_;
};

}  // namespace lfd::serve
