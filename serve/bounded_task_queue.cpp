// A bounded task queue for cpp-httplib (docs/serve.md).
#include "serve/bounded_task_queue.hpp"

namespace lfd::serve {

BoundedTaskQueue::BoundedTaskQueue(int workers, int max_pending)
    : max_pending_(static_cast<std::size_t>(max_pending)) {
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

BoundedTaskQueue::~BoundedTaskQueue() { shutdown(); }

void BoundedTaskQueue::enqueue(std::function<void()> fn) {
  std::unique_lock lock(mutex_);
  has_room_.wait(lock, [&] { return shutdown_ || jobs_.size() < max_pending_; });
  jobs_.push_back(std::move(fn));  // after shutdown the job still runs: it closes its socket
  lock.unlock();
  has_job_.notify_one();
}

void BoundedTaskQueue::work() {
  for (;;) {
    std::function<void()> fn;
    {
      std::unique_lock lock(mutex_);
      has_job_.wait(lock, [&] { return shutdown_ || !jobs_.empty(); });
      if (jobs_.empty()) return;
      fn = std::move(jobs_.front());
      jobs_.pop_front();
    }
    has_room_.notify_one();
    fn();
  }
}

void BoundedTaskQueue::shutdown() {
  {
    std::lock_guard lock(mutex_);
    if (shutdown_ && threads_.empty()) return;
    shutdown_ = true;
  }
  has_job_.notify_all();
  has_room_.notify_all();
  for (auto& t : threads_) t.join();
  threads_.clear();
}

}  // namespace lfd::serve
