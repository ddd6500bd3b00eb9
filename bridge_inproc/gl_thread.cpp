#include "bridge_inproc/gl_thread.hpp"

#include "bridge_inproc/bridge_log.hpp"

namespace lfd::bridge {

GlThread::GlThread() : thread_([this] { loop(); }) {}

GlThread::~GlThread() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void GlThread::post(unsigned long key, const std::string& call_name, std::function<void()> task) {
  enqueue(key, call_name, std::move(task));
}

void GlThread::enqueue(unsigned long key, const std::string& call_name, std::function<void()> run) {
  {
    std::lock_guard lock(mutex_);
    if (key != 0)
      for (Task& t : tasks_)
        if (t.key == key) {
          t.run = std::move(run);  // the newest frame takes the waiting one's place
          t.call_name = call_name;
          wake_.notify_all();
          return;
        }
    tasks_.push_back({key, call_name, std::move(run)});
  }
  wake_.notify_all();
}

void GlThread::loop() {
  for (;;) {
    Task task;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (tasks_.empty()) return;  // stopping, nothing left
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    try {
      task.run();
    } catch (const std::exception& e) {
      log_line(task.call_name, e.what());
    } catch (...) {
      log_line(task.call_name, "unknown failure");
    }
  }
}

}  // namespace lfd::bridge
