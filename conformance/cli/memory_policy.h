// How voxref asks the C library to manage its heap. voxref's large working arrays (the meshes,
// page caches and hash tables of the isosurface frames, the decode buffers) are freed and made
// again over and over; by default glibc gives every block above its mmap threshold (at most
// 32 MiB, dynamic) back to the kernel when it is freed, so the next block of that size is fresh
// memory whose every page faults on first touch. On the virtual machines voxref is measured on a
// page fault costs several microseconds, and the faults were a seventh of the time of the
// isosurface frames' extraction (docs/iso.md, "Figures").
#pragma once

namespace voxref::cli {

// Blocks up to 1 GiB come from the heap, and freed memory stays in it for the next block (the
// heap is not trimmed until 1 GiB is free at its top). Results never depend on it: only where
// memory comes from and how often the kernel faults it in. Peak resident memory stays what the
// program holds at its peak (a freed block is reused before the heap grows). Call once, first.
void keepFreedMemoryForReuse();

}  // namespace voxref::cli
