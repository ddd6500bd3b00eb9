// The memory budget (docs/serve.md, "Memory").
#include "serve/memory_budget.hpp"

#include <malloc.h>

#include <algorithm>
#include <fstream>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::serve {

MemoryBudget::Reservation& MemoryBudget::Reservation::operator=(Reservation&& other) noexcept {
  if (this != &other) {
    release();
    counter_ = std::move(other.counter_);
    bytes_ = other.bytes_;
    other.bytes_ = 0;
  }
  return *this;
}

void MemoryBudget::Reservation::release() {
  if (counter_) counter_->used -= bytes_;
  counter_.reset();
  bytes_ = 0;
}

MemoryBudget::Reservation MemoryBudget::Reservation::split(std::size_t bytes) {
  Reservation part;
  if (!counter_) return part;
  part.counter_ = counter_;
  part.bytes_ = std::min(bytes, bytes_);
  bytes_ -= part.bytes_;
  return part;
}

void MemoryBudget::Reservation::merge(Reservation other) {
  if (!other.counter_) return;
  if (!counter_) counter_ = other.counter_;
  bytes_ += other.bytes_;
  other.bytes_ = 0;
  other.counter_.reset();
}

MemoryBudget::MemoryBudget(std::size_t limit_bytes) : counter_(std::make_shared<Counter>()) {
  counter_->limit = limit_bytes;
}

namespace {

// Whether `bytes` more would take the process past `resident_limit` (0: no limit). Reading
// /proc costs microseconds: asked only for reservations of a megabyte or more (content).
bool passes_resident_limit(std::size_t bytes, std::size_t resident_limit) {
  if (resident_limit == 0 || bytes < MemoryBudget::kResidentCheckFrom) return false;
  const std::size_t resident = resident_bytes();
  return bytes > resident_limit || resident > resident_limit - bytes;
}

}  // namespace

MemoryBudget::Reservation MemoryBudget::try_reserve(std::size_t bytes) {
  if (passes_resident_limit(bytes, counter_->resident_limit)) {
    ++counter_->refused;
    return {};
  }
  std::size_t used = counter_->used.load();
  do {
    if (bytes > counter_->limit || used > counter_->limit - bytes) {
      ++counter_->refused;
      return {};
    }
  } while (!counter_->used.compare_exchange_weak(used, used + bytes));
  Reservation r;
  r.counter_ = counter_;
  r.bytes_ = bytes;
  return r;
}

MemoryBudget::Reservation MemoryBudget::reserve_or_busy(std::size_t bytes, const std::string& what) {
  constexpr double kMiB = 1 << 20;
  if (bytes > counter_->limit)
    throw_input_error("{} needs {:.0f} MiB, more than the service's memory budget leaves for requests ({:.0f} MiB; "
                      "--memory-budget)",
                      what, bytes / kMiB, counter_->limit / kMiB);
  Reservation r = try_reserve(bytes);
  if (!r && passes_resident_limit(bytes, counter_->resident_limit))
    throw BusyError(fmt::format("busy: {} needs {:.0f} MiB and the service holds {:.0f} of its {:.0f} MiB memory budget "
                                "(requests being read and handled); try again",
                                what, bytes / kMiB, resident_bytes() / kMiB, counter_->resident_limit / kMiB));
  if (!r)
    throw BusyError(fmt::format("busy: {} needs {:.0f} MiB and {:.0f} of the {:.0f} MiB memory budget are in use; try again",
                                what, bytes / kMiB, used() / kMiB, counter_->limit / kMiB));
  return r;
}

void return_large_buffers_to_the_system() { mallopt(M_MMAP_THRESHOLD, 256 * 1024); }

void MemoryBudget::set_aside(std::size_t bytes, const std::string& what) {
  if (bytes >= counter_->limit)
    throw_input_error("{} holds {} MiB, more than the memory budget of {} MiB (--memory-budget)", what, bytes >> 20,
                      counter_->limit >> 20);
  counter_->limit -= bytes;
}

std::size_t resident_bytes(int pid) {
  std::ifstream status(pid > 0 ? fmt::format("/proc/{}/status", pid) : std::string("/proc/self/status"));
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stoul(line.substr(6)) * 1024;
  return 0;
}

}  // namespace lfd::serve
