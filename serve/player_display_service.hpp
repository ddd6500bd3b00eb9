#pragma once
// DisplayService on `lfd play`'s Players (play/player.hpp), one per served display: what
// `lfd serve` runs. Quilts shown in memory, playlists of checked files, transport and events go
// through each Player's thread-safe command queue; the Players' frames run on the main thread
// (apps/serve.cpp). What the Player cannot do is refused with a message, never pretended
// (docs/serve.md). A quilt handed to a Player reserves its memory from the service's budget for
// as long as it waits or is shown; one that does not fit is busy (docs/serve.md, "Memory").
#include <cstdint>
#include <map>
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
  void update_current_entry(const std::string& parameter, double value) override;
  void show_window(bool show) override;
  PlaybackState state() const override;
  void set_event_listener(std::function<void(const PlaybackEvent&)> listener) override;

 private:
  play::Player& player(int display) const;
  void on_player_event(int display, const play::PlaybackEvent& event);

  std::vector<play::Player*> players_;
  std::vector<ServedDisplay> displays_;
  std::vector<int> subscriptions_;
  mutable std::mutex mutex_;
  MemoryBudget& budget_;
  std::string playlist_;      // the playlist the first display plays, empty if none
  int playlist_display_ = 0;
  std::string showing_;       // what was last shown through the service
  std::function<void(const PlaybackEvent&)> listener_;
};

}  // namespace lfd::serve
