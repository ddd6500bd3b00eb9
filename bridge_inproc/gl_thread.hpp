#pragma once
// The library's drawing thread (docs/bridge-inproc.md "Threads"): every GL call of lfd's own
// contexts and every GLFW call of the library run here, so a client's thread is held only for the
// copy of its texture. Calls that answer (making a window, reading a panel) wait for their task;
// frames are posted and the newest waiting frame of a window replaces an older one that has not
// started (a client drawing faster than the display shows drops frames instead of queueing them).
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <string>
#include <thread>

namespace lfd::bridge {

class GlThread {
 public:
  GlThread();
  ~GlThread();  // runs what is queued, then stops
  GlThread(const GlThread&) = delete;
  GlThread& operator=(const GlThread&) = delete;

  // Runs `task` on the thread and waits for it; its exception is rethrown here.
  template <typename F>
  auto call(F task) -> decltype(task()) {
    std::packaged_task<decltype(task())()> packaged(std::move(task));
    auto result = packaged.get_future();
    enqueue(0, "", [&packaged] { packaged(); });
    return result.get();
  }
  // Queues `task`; a task of the same non-zero `key` still waiting is dropped for it. An
  // exception is logged under `call_name`.
  void post(unsigned long key, const std::string& call_name, std::function<void()> task);

 private:
  struct Task {
    unsigned long key = 0;
    std::string call_name;
    std::function<void()> run;
  };
  void enqueue(unsigned long key, const std::string& call_name, std::function<void()> run);
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Task> tasks_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace lfd::bridge
