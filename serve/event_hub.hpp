#pragma once
// Fan-out of Bridge events (JSON text) to the event socket's connections; thread-safe. The Bridge
// API publishes what its calls did, the service forwards the display's playback events.
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace lfd::serve {

class EventHub {
 public:
  using Listener = std::function<void(const std::string& json_text)>;
  int subscribe(Listener listener);
  void unsubscribe(int id);
  void publish(const std::string& json_text);
  std::size_t published() const;

 private:
  mutable std::mutex mutex_;
  std::map<int, Listener> listeners_;
  int next_id_ = 1;
  std::size_t published_ = 0;
};

}  // namespace lfd::serve
