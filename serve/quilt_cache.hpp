#pragma once
// The named quilts of holoplay `cache` (shown later by `show` with source "cache"), decoded and
// kept in memory under a count and byte limit: the oldest go first. Thread-safe.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "serve/display_service.hpp"

namespace lfd::serve {

struct CachedQuilt {
  std::string name;
  std::shared_ptr<const Image8> image;
  QuiltSettings settings;
};

class QuiltCache {
 public:
  QuiltCache(std::size_t max_bytes, int max_count) : max_bytes_(max_bytes), max_count_(max_count) {}
  void put(CachedQuilt quilt);  // replaces one of the same name; evicts the oldest over the limits
  std::optional<CachedQuilt> get(const std::string& name) const;
  bool contains(const std::string& name) const;
  bool erase(const std::string& name);
  std::size_t size() const;
  std::size_t bytes() const;

 private:
  mutable std::mutex mutex_;
  std::list<CachedQuilt> quilts_;  // oldest first
  std::size_t bytes_ = 0;
  std::size_t max_bytes_;
  int max_count_;
};

}  // namespace lfd::serve
