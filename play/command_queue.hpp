#pragma once
// The Player's command queue (play/player.hpp, "Threads"): commands from any thread, taken in
// the order they came by the GL thread at the start of a frame. A content command (show a quilt,
// set a playlist) replaces the content commands still waiting: what they would show is never
// drawn, so they are dropped, and the pictures they hold go with them. A client sending quilts
// faster than the display draws (lfd serve, docs/serve.md "Memory") then costs one waiting
// picture, not a backlog. Other commands (play, pause, aspect, ...) all stay, in order.
// Thread-safe; no GL, so it is tested alone (tests/serve/replaced_show_test.cpp).
#include <cstddef>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

namespace lfd::play {

template <class Target>
class CommandQueue {
 public:
  using Command = std::function<void(Target&)>;

  void push(Command command) {
    std::lock_guard lock(mutex_);
    waiting_.push_back({false, std::move(command)});
  }

  void push_content(Command command) {
    std::vector<Waiting> replaced;  // destroyed outside the lock (a picture can be large)
    {
      std::lock_guard lock(mutex_);
      for (auto it = waiting_.begin(); it != waiting_.end();) {
        if (it->content) {
          replaced.push_back(std::move(*it));
          it = waiting_.erase(it);
        } else {
          ++it;
        }
      }
      dropped_ += replaced.size();
      waiting_.push_back({true, std::move(command)});
    }
  }

  // Every waiting command, in order; the queue is empty after.
  std::vector<Command> take() {
    std::vector<Waiting> now;
    {
      std::lock_guard lock(mutex_);
      now.swap(waiting_);
    }
    std::vector<Command> out;
    out.reserve(now.size());
    for (auto& w : now) out.push_back(std::move(w.command));
    return out;
  }

  std::size_t dropped() const {  // content commands replaced before they were taken
    std::lock_guard lock(mutex_);
    return dropped_;
  }

 private:
  struct Waiting {
    bool content = false;
    Command command;
  };
  mutable std::mutex mutex_;
  std::vector<Waiting> waiting_;
  std::size_t dropped_ = 0;
};

}  // namespace lfd::play
