// The holoplay quilt cache (docs/serve.md).
#include "serve/quilt_cache.hpp"

#include <algorithm>

#include "util/error.hpp"

namespace lfd::serve {

namespace {
std::size_t bytes_of(const CachedQuilt& q) { return q.image ? q.image->pixels.size() : 0; }
}  // namespace

void QuiltCache::put(CachedQuilt quilt) {
  if (bytes_of(quilt) > max_bytes_)
    throw_input_error("cache {}: the quilt is larger than the cache ({} bytes)", quilt.name, max_bytes_);
  std::lock_guard lock(mutex_);
  auto same = std::find_if(quilts_.begin(), quilts_.end(), [&](const auto& q) { return q.name == quilt.name; });
  if (same != quilts_.end()) {
    bytes_ -= bytes_of(*same);
    quilts_.erase(same);
  }
  bytes_ += bytes_of(quilt);
  quilts_.push_back(std::move(quilt));
  while (bytes_ > max_bytes_ || static_cast<int>(quilts_.size()) > max_count_) {
    bytes_ -= bytes_of(quilts_.front());
    quilts_.pop_front();
  }
}

std::optional<CachedQuilt> QuiltCache::get(const std::string& name) const {
  std::lock_guard lock(mutex_);
  for (const auto& q : quilts_)
    if (q.name == name) return q;
  return std::nullopt;
}

bool QuiltCache::contains(const std::string& name) const { return get(name).has_value(); }

bool QuiltCache::erase(const std::string& name) {
  std::lock_guard lock(mutex_);
  auto it = std::find_if(quilts_.begin(), quilts_.end(), [&](const auto& q) { return q.name == name; });
  if (it == quilts_.end()) return false;
  bytes_ -= bytes_of(*it);
  quilts_.erase(it);
  return true;
}

std::size_t QuiltCache::size() const {
  std::lock_guard lock(mutex_);
  return quilts_.size();
}

std::size_t QuiltCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace lfd::serve
