#include "dfvn/core/bulk_memory.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdio>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::uintptr_t kPage = 4096;

std::uintptr_t round_up(std::uintptr_t x, std::uintptr_t to) { return (x + to - 1) / to * to; }

}  // namespace

OutOfMemory::OutOfMemory(double bytes) {
  std::snprintf(message_, sizeof message_, "out of memory: cannot allocate %s; try a smaller problem", byte_size(bytes).c_str());
}

// The block starts on a huge-page boundary (mapped with a huge page of slack, the unaligned head and
// the tail beyond the block unmapped again), so every whole 2 MB of it can be one huge page.
void* map_pages(std::size_t bytes) {
  if (bytes == 0 || bytes > std::size_t(-1) / 2) throw OutOfMemory(static_cast<double>(bytes));
  const std::uintptr_t length = round_up(bytes, kPage);
  void* p = mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw OutOfMemory(static_cast<double>(bytes));
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t aligned = round_up(start, kHugePage);
  if (aligned > start) munmap(p, aligned - start);
  const std::uintptr_t end = start + length + kHugePage;
  if (end > aligned + length) munmap(reinterpret_cast<void*>(aligned + length), end - (aligned + length));
  void* block = reinterpret_cast<void*>(aligned);
#ifdef MADV_HUGEPAGE
  madvise(block, length, MADV_HUGEPAGE);  // advice: without huge pages the memory works the same
#endif
  return block;
}

void release_pages(void* p, std::size_t bytes) noexcept {
  if (p) munmap(p, bytes);
}

}  // namespace dfvn
