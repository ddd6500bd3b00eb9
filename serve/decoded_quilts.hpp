#pragma once
// Quilt images decoded once per distinct content (docs/serve.md, "Memory"): the bytes of a
// HoloPlay `show` or `cache` are looked up by their hash and size first, so a page or a kiosk
// sending the same quilt again costs a hash, not a decode. A decode first takes one of
// ServeLimits::max_decodes slots and reserves its memory from the budget (the picture, and
// stb's buffer beside it while it decodes), or is busy at once. A decoded picture carries its
// reservation: the bytes count for as long as anyone (this cache, the named cache, the display)
// holds the picture. Thread-safe.
#include <atomic>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <span>
#include <string>

#include "serve/memory_budget.hpp"
#include "serve/serve_limits.hpp"
#include "util/image.hpp"

namespace lfd::serve {

class DecodedQuilts {
 public:
  DecodedQuilts(MemoryBudget& budget, const ServeLimits& limits);
  // The RGB picture of `bytes` (PNG, JPEG, WebP). BusyError when no decode slot is free or the
  // budget cannot take it now; InputError for bytes that are not a picture within the bounds.
  std::shared_ptr<const Image8> decode(std::span<const std::uint8_t> bytes, const std::string& name);
  std::size_t decodes() const { return decodes_; }  // pictures actually decoded

 private:
  struct Entry {
    std::uint64_t hash = 0;
    std::size_t size = 0;
    std::shared_ptr<const Image8> image;
  };
  std::shared_ptr<const Image8> find(std::uint64_t hash, std::size_t size);
  // A reservation of `bytes`, dropping kept pictures (oldest first) to make room; BusyError.
  MemoryBudget::Reservation reserve(std::size_t bytes, const std::string& what);

  MemoryBudget& budget_;
  const ServeLimits& limits_;
  std::mutex mutex_;
  std::list<Entry> kept_;  // oldest first
  std::atomic<int> decoding_{0};
  std::atomic<std::size_t> decodes_{0};
};

}  // namespace lfd::serve
