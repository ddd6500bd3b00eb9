#pragma once
// A moving scene played in real time (docs/viewer.md "Moving scenes"): the frames of a sequence
// (scene/scene_sequence.hpp) read from disk on a thread of their own, ahead of the frame shown, at
// most `ahead` frames in memory besides the one shown, so a sequence of any length plays in
// bounded memory. The player asks for the frame its clock says; a frame not read yet is not
// waited for (the player keeps showing the last one) unless it asks to wait (scripted runs).
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "scene/scene.hpp"
#include "scene/scene_sequence.hpp"

namespace lfd::scene {

class SceneStream {
 public:
  // Starts reading from frame 0; `ahead` >= 1.
  SceneStream(SceneSequence sequence, int ahead = 3);
  ~SceneStream();
  SceneStream(const SceneStream&) = delete;
  SceneStream& operator=(const SceneStream&) = delete;

  int count() const { return int(sequence_.frames.size()); }
  // Frame `index` (0..count-1) if read, else null (wait: block until it is). Frames before
  // `index` are dropped and reading moves on from it, looping at the end. InputError naming the
  // file when that frame could not be read.
  std::shared_ptr<const Scene> frame(int index, bool wait = false);
  // Frames held in memory now (the shown one and those read ahead): at most ahead + 1.
  int frames_held() const;

 private:
  void read_ahead();

  SceneSequence sequence_;
  int ahead_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<int, std::shared_ptr<const Scene>> frames_;
  std::map<int, std::string> errors_;
  int wanted_ = 0;  // the frame shown: reading fills wanted_ .. wanted_ + ahead_ (mod count)
  bool stop_ = false;
  std::thread reader_;
};

}  // namespace lfd::scene
