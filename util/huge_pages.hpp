#pragma once
// Large image and plane buffers backed by transparent huge pages. Why: a fresh 4 KiB page costs
// a page fault on first touch, about 18 us each on the virtual machines lfd is measured on
// (docs/performance.md), so zeroing a 141 MB quilt took 0.65 s on one core before any pixel was
// computed, and touching it from two threads was no faster. With 2 MiB pages it takes 0.02 s.
// Linux only (THP in "always" or "madvise" mode); elsewhere, or when the kernel refuses, the
// buffers are ordinary memory.
#include <cstddef>
#include <vector>

namespace lfd {

// Buffers smaller than this are left alone: they come from the malloc heap, and a huge page
// would not be filled.
constexpr size_t kHugePageMinBytes = size_t(4) << 20;

// Advises the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge pages.
// Call it before the memory is first touched; it never fails (the advice may be ignored).
void advise_huge_pages(void* data, size_t bytes);

// v.assign(n, fill), the storage advised for huge pages before it is first touched when it is
// newly allocated and large.
template <typename T>
void assign_large(std::vector<T>& v, size_t n, const T& fill) {
  if (v.capacity() < n && n * sizeof(T) >= kHugePageMinBytes) {
    std::vector<T>().swap(v);
    v.reserve(n);
    advise_huge_pages(v.data(), n * sizeof(T));
  }
  v.assign(n, fill);
}

}  // namespace lfd
