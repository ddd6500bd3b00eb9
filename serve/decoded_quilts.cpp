// Quilts decoded once per content (docs/serve.md, "Memory").
#include "serve/decoded_quilts.hpp"

#include <functional>
#include <string_view>

#include <fmt/format.h>

#include "media/quilt_image.hpp"

namespace lfd::serve {

DecodedQuilts::DecodedQuilts(MemoryBudget& budget, const ServeLimits& limits) : budget_(budget), limits_(limits) {}

std::shared_ptr<const Image8> DecodedQuilts::find(std::uint64_t hash, std::size_t size) {
  std::lock_guard lock(mutex_);
  for (auto it = kept_.begin(); it != kept_.end(); ++it)
    if (it->hash == hash && it->size == size) {
      kept_.splice(kept_.end(), kept_, it);  // the newest again
      return kept_.back().image;
    }
  return nullptr;
}

MemoryBudget::Reservation DecodedQuilts::reserve(std::size_t bytes, const std::string& what) {
  for (;;) {
    if (auto r = budget_.try_reserve(bytes)) return r;
    std::shared_ptr<const Image8> dropped;  // freed outside the lock
    {
      std::lock_guard lock(mutex_);
      if (kept_.empty()) break;
      dropped = std::move(kept_.front().image);
      kept_.pop_front();
    }
  }
  return budget_.reserve_or_busy(bytes, what);  // busy (or more than the whole budget)
}

std::shared_ptr<const Image8> DecodedQuilts::decode(std::span<const std::uint8_t> bytes, const std::string& name) {
  const std::uint64_t hash =
      std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  if (auto image = find(hash, bytes.size())) return image;
  const media::ImageSize size = media::image_size(bytes, name);
  const std::size_t pixel_bytes = std::size_t(size.width) * size.height * 3;
  // Decoding is the CPU-heavy part: a bounded number at once keeps workers for cheap requests.
  if (++decoding_ > limits_.max_decodes) {
    --decoding_;
    throw BusyError(fmt::format("busy: {} quilts are being decoded; try again", limits_.max_decodes));
  }
  struct Slot {
    std::atomic<int>& n;
    ~Slot() { --n; }
  } slot{decoding_};
  const std::string what = fmt::format("{} ({}x{})", name, size.width, size.height);
  // The picture, and stb's own buffer of the same size beside it while it decodes.
  MemoryBudget::Reservation decoding = reserve(2 * pixel_bytes, what);
  auto kept = std::make_shared<MemoryBudget::Reservation>(decoding.split(pixel_bytes));
  auto decoded = std::make_unique<Image8>(media::decode_image(bytes, name));
  decoding.release();
  std::shared_ptr<const Image8> image(decoded.release(), [kept](const Image8* p) { delete p; });
  ++decodes_;
  std::lock_guard lock(mutex_);
  kept_.push_back({hash, bytes.size(), image});
  while (static_cast<int>(kept_.size()) > limits_.decoded_quilts_kept) kept_.pop_front();
  return image;
}

}  // namespace lfd::serve
