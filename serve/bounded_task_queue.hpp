#pragma once
// cpp-httplib's task queue with a bound (docs/serve.md, "Security model"): a fixed pool of
// workers and at most `max_pending` accepted connections waiting for one; past that, enqueue
// waits, so the accept loop stops accepting and further clients wait in the kernel's listen
// backlog instead of growing a queue without end (httplib's own ThreadPool has no bound).
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <httplib.h>

namespace lfd::serve {

class BoundedTaskQueue : public httplib::TaskQueue {
 public:
  BoundedTaskQueue(int workers, int max_pending);
  ~BoundedTaskQueue() override;
  void enqueue(std::function<void()> fn) override;
  void shutdown() override;

 private:
  void work();
  std::mutex mutex_;
  std::condition_variable has_job_, has_room_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  std::size_t max_pending_;
  bool shutdown_ = false;
};

}  // namespace lfd::serve
