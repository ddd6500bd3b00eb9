// Event fan-out (docs/serve.md, "Events").
#include "serve/event_hub.hpp"

namespace lfd::serve {

int EventHub::subscribe(Listener listener) {
  std::lock_guard lock(mutex_);
  listeners_[next_id_] = std::move(listener);
  return next_id_++;
}

void EventHub::unsubscribe(int id) {
  std::lock_guard lock(mutex_);
  listeners_.erase(id);
}

void EventHub::publish(const std::string& json_text) {
  std::lock_guard lock(mutex_);
  ++published_;
  for (auto& [id, listener] : listeners_) listener(json_text);
}

std::size_t EventHub::published() const {
  std::lock_guard lock(mutex_);
  return published_;
}

}  // namespace lfd::serve
