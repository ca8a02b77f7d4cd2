// How much freed memory a process that recognises cloud after cloud keeps for the next one:
// glibc's thresholds, set once at start-up (execution.retained_memory_mb).
#pragma once

#include <cstdint>

namespace cloudshape::parallel {

// Keeps up to `megabytes` of freed memory in the process (glibc's trim threshold) and serves
// blocks up to that size, or 32 MB (glibc's ceiling) if less, from the heap, so that a frame's
// buffers are not faulted in page by page again for every frame. 0 or less: the C library's own
// thresholds.
void retain_freed_memory(std::int64_t megabytes);

}  // namespace cloudshape::parallel
