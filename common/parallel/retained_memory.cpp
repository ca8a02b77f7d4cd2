#include "parallel/retained_memory.hpp"

#include <malloc.h>

#include <algorithm>
#include <climits>

namespace cloudshape::parallel {

// glibc hands blocks above its mmap threshold back to the system when freed and trims the heap
// top above its trim threshold: a 640 x 480 frame's buffers (points, graph, grids: tens of MB)
// were then faulted in page by page again for every frame (11% of ingest's CPU; 79 000 page
// faults in 45 Kinect frames of the scene benchmark, 6 400 with them kept).
void retain_freed_memory(std::int64_t megabytes) {
  if (megabytes <= 0) return;
  constexpr std::int64_t kMaxMmapThreshold = 32 << 20;  // glibc's ceiling on 64-bit hosts
  const std::int64_t bytes = std::min<std::int64_t>(megabytes, INT32_MAX >> 20) << 20;
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(bytes));
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(std::min(bytes, kMaxMmapThreshold)));
}

}  // namespace cloudshape::parallel
