#pragma once
// The service's memory budget (docs/serve.md, "Memory"): one count of the bytes that requests'
// content holds while it waits (messages being decoded, decoded quilts, pictures handed to the
// display, cached quilts, Bridge bodies, queued events), against the one limit
// ServeLimits::memory_budget_bytes. A request whose content does not fit now is answered busy
// at once (BusyError) instead of waiting: memory stays bounded in bytes, not in requests.
// Thread-safe; a Reservation may outlive the budget.
#include <atomic>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>

namespace lfd::serve {

// "Try again later": HoloPlay's error 6, Bridge's Failure with HTTP 503 and Retry-After.
struct BusyError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class MemoryBudget {
  struct Counter {
    std::atomic<std::size_t> used{0};
    std::atomic<std::size_t> refused{0};
    std::atomic<std::size_t> limit{0};
    std::atomic<std::size_t> resident_limit{0};  // 0: resident memory not consulted
  };

 public:
  // Bytes held until destroyed (or moved from); empty when nothing was taken.
  class Reservation {
   public:
    Reservation() = default;
    Reservation(Reservation&& other) noexcept { *this = std::move(other); }
    Reservation& operator=(Reservation&& other) noexcept;
    Reservation(const Reservation&) = delete;
    Reservation& operator=(const Reservation&) = delete;
    ~Reservation() { release(); }
    std::size_t bytes() const { return bytes_; }
    explicit operator bool() const { return counter_ != nullptr; }
    void release();
    // Moves `bytes` of this reservation (at most all of it) into a new one: part of what was
    // reserved for a job stays with its result.
    Reservation split(std::size_t bytes);
    // Takes over `other`'s bytes (of the same budget), so one reservation holds both.
    void merge(Reservation other);

   private:
    friend class MemoryBudget;
    std::shared_ptr<Counter> counter_;
    std::size_t bytes_ = 0;
  };

  explicit MemoryBudget(std::size_t limit_bytes);
  // `bytes` if they fit under the limit now, else an empty reservation (counted as refused).
  Reservation try_reserve(std::size_t bytes);
  // try_reserve, or BusyError naming `what` and the budget. A request that could never fit
  // (more than the whole budget) gets InputError instead: waiting would not help.
  Reservation reserve_or_busy(std::size_t bytes, const std::string& what);
  // Takes `bytes` off the limit for good: what the process holds before any request (its
  // windows, GL, libraries). InputError naming `what` when that is more than the limit.
  void set_aside(std::size_t bytes, const std::string& what);
  // What the whole process may hold (the --memory-budget before set_aside): from now on a
  // reservation of kResidentCheckFrom bytes or more is also refused while the process's resident
  // memory and it would pass this. What the count cannot see (NNG reading a message off a
  // connection before the service is handed it, heap slack) then stops new work instead of
  // adding to it (docs/serve.md, "Memory").
  void limit_resident(std::size_t total_bytes) { counter_->resident_limit = total_bytes; }
  static constexpr std::size_t kResidentCheckFrom = 1u << 20;
  std::size_t used() const { return counter_->used; }
  std::size_t limit() const { return counter_->limit; }
  std::size_t refused() const { return counter_->refused; }

 private:
  std::shared_ptr<Counter> counter_;
};

// Large buffers (quilts, messages) from mmap from now on, returned to the system when freed:
// glibc's sliding threshold would otherwise move them into its heaps, which keep them resident
// after the request, so resident memory would follow the peak, not what is held (lfd serve
// calls it at start).
void return_large_buffers_to_the_system();

// A process's resident memory now (VmRSS of /proc/PID/status; pid 0: this process), 0 when
// there is none.
std::size_t resident_bytes(int pid = 0);

}  // namespace lfd::serve
