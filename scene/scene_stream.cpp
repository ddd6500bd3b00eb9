#include "scene/scene_stream.hpp"

#include "util/error.hpp"

namespace lfd::scene {

SceneStream::SceneStream(SceneSequence sequence, int ahead)
    : sequence_(std::move(sequence)), ahead_(std::max(1, ahead)), reader_([this] { read_ahead(); }) {}

SceneStream::~SceneStream() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  reader_.join();
}

int SceneStream::frames_held() const {
  std::lock_guard lock(mutex_);
  return int(frames_.size());
}

void SceneStream::read_ahead() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    // The next frame of the window wanted_ .. wanted_ + ahead_ not read yet (the window loops).
    std::optional<int> next;
    const int window = std::min(ahead_ + 1, count());
    for (int k = 0; k < window && !next; ++k) {
      const int index = (wanted_ + k) % count();
      if (!frames_.count(index) && !errors_.count(index)) next = index;
    }
    if (!next) {
      changed_.wait(lock);
      continue;
    }
    lock.unlock();
    std::shared_ptr<const Scene> scene;
    std::string error;
    try {
      scene = std::make_shared<const Scene>(load_scene(sequence_.frames[size_t(*next)]));
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    if (scene) frames_[*next] = std::move(scene);
    else errors_[*next] = error;
    changed_.notify_all();
  }
}

std::shared_ptr<const Scene> SceneStream::frame(int index, bool wait) {
  std::unique_lock lock(mutex_);
  if (index != wanted_) {
    wanted_ = index;
    // Keep only the window from the new frame on: memory stays bounded however long it plays.
    const int window = std::min(ahead_ + 1, count());
    for (auto it = frames_.begin(); it != frames_.end();)
      it = (it->first - index + count()) % count() < window ? std::next(it) : frames_.erase(it);
    changed_.notify_all();
  }
  if (wait) changed_.wait(lock, [&] { return frames_.count(index) || errors_.count(index); });
  if (const auto e = errors_.find(index); e != errors_.end()) throw InputError(e->second);
  const auto it = frames_.find(index);
  return it == frames_.end() ? nullptr : it->second;
}

}  // namespace lfd::scene
