// Memory for large arrays (point sets, grids): anonymous pages on transparent huge pages where the
// system offers them, and no fill pass. A std::vector zero-fills what it allocates and the kernel
// faults it in 4 KB at a time (13-16 us a fault on this kind of shared machine), which made a 7D
// 2^18-point Sobol set 10x dearer than its kernel; NumPy takes huge pages for arrays of 4 MB and up.
#pragma once

#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace dfvn {

// Arrays of at least this many bytes get their own pages (with huge-page advice); smaller ones come
// from operator new, where reuse of freed memory beats fresh pages.
inline constexpr std::size_t kBulkPagesFrom = std::size_t{4} << 20;

// std::bad_alloc that says how much was asked for ("out of memory: cannot allocate 1.50 TiB"), so that a
// refusal names the size (the command line's and Python's MemoryError print what()).
class OutOfMemory : public std::bad_alloc {
 public:
  explicit OutOfMemory(double bytes);
  const char* what() const noexcept override { return message_; }

 private:
  char message_[96];
};

// `bytes` (> 0) of zero-filled anonymous pages, advised to use huge pages; OutOfMemory when the
// system refuses. Release with release_pages(p, bytes) and the same byte count.
void* map_pages(std::size_t bytes);
void release_pages(void* p, std::size_t bytes) noexcept;

// An allocator whose value-less construct() leaves trivial elements uninitialised, so vector(n) and
// resize(n) write nothing (the caller fills every element), and whose large blocks come from
// map_pages(). Only for arrays whose every element is written before it is read.
template <class T>
struct BulkAllocator {
  static_assert(std::is_trivially_copyable_v<T>, "bulk arrays hold plain numbers");
  using value_type = T;

  BulkAllocator() noexcept = default;
  template <class U>
  BulkAllocator(const BulkAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw OutOfMemory(static_cast<double>(n) * sizeof(T));
    const std::size_t bytes = n * sizeof(T);
    if (bytes >= kBulkPagesFrom) return static_cast<T*>(map_pages(bytes));
    return static_cast<T*>(::operator new(bytes, std::align_val_t{alignof(T)}));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes >= kBulkPagesFrom)
      release_pages(p, bytes);
    else
      ::operator delete(p, std::align_val_t{alignof(T)});
  }

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialised: no write for numbers
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const BulkAllocator<U>&) const noexcept {
    return true;
  }
};

// A point set's coordinates: points x dimension doubles, row-major, every one written by its maker.
using Coordinates = std::vector<double, BulkAllocator<double>>;

}  // namespace dfvn
