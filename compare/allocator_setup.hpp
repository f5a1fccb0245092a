#pragma once
// glibc's allocator tuned for granmix's pattern of work: the theory levels allocate and free the same large blocks
// (Galerkin and speed-grid matrices, 0.1–30 MB) at every pass, which by default go back to the system (mmap above
// 128 kB, the heap trimmed above 128 kB free) and come back as fresh zero pages — page faults then take 14% of v1 Fig. 5's
// judged level (0.31 of 2.28 s in the kernel). Keeping freed memory in the process costs its peak resident size,
// which these levels have reached anyway.
namespace granmix::compare {

// Blocks up to 32 MB (glibc's largest mmap threshold) from the heap, which is trimmed only above 512 MB free and grows
// 64 MB at a time. A refused setting (another allocator, e.g. a sanitizer's) leaves the default: speed only.
void keep_freed_memory();

}  // namespace granmix::compare
