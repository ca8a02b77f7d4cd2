// Freed memory kept for the next cloud: a frame-sized buffer comes from the heap, and once freed
// stays there for the next frame instead of going back to the system.
#include <gtest/gtest.h>
#include <malloc.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

#include "parallel/retained_memory.hpp"

namespace cloudshape::parallel {
namespace {

TEST(RetainedMemory, AFreedFrameBufferStaysInTheHeap) {
  // A sanitizer's allocator replaces glibc's: its mallinfo2 reports nothing, and these thresholds
  // are not its own.
  if (mallinfo2().arena == 0) GTEST_SKIP() << "mallinfo2 reports no heap: not glibc's allocator";
  retain_freed_memory(64);
  constexpr std::size_t kBytes = 24 << 20;  // a 640 x 480 frame's points three times over
  void* block = std::malloc(kBytes);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, kBytes);
  const struct mallinfo2 held = mallinfo2();
  std::free(block);
  const struct mallinfo2 freed = mallinfo2();
  // glibc's defaults map such a block on its own (and unmap it when freed) and trim a heap top
  // this large: neither here.
  EXPECT_LT(held.hblkhd, kBytes) << "the block was mapped on its own";
  EXPECT_GE(freed.fordblks, kBytes) << "the freed block went back to the system";
}

}  // namespace
}  // namespace cloudshape::parallel
