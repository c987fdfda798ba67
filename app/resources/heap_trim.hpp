#pragma once
// The glibc trim threshold raised so that freed heap memory stays with the process.

namespace grainload::app {

/// Heap memory freed at the top of glibc's heap below this many bytes stays with the process
/// instead of going back to the kernel at once. VTK's zlib compressor allocates and frees a
/// buffer of about 256 KiB for every array of every frame; with glibc's default threshold
/// (128 KiB, adapted upwards only by freed mmap chunks) each free shrank the heap, and each
/// shrink cost a TLB shoot-down across the cores: on the 2-vCPU AMD EPYC machine of
/// docs/performance.md the CI hopper (`grainload run
/// cases/hopper_discharge/hopper_discharge_small.toml --threads 1`, 61 frames) spent 0.95 s of
/// its 2.8 s of CPU in the kernel, 0.35 s with this threshold (docs/performance.md, "Frames and the
/// heap").
inline constexpr int kHeapTrimThreshold = 64 << 20;

/// Sets the threshold (mallopt M_TRIM_THRESHOLD, glibc); call first thing in main.
void keep_freed_heap();

} // namespace grainload::app
