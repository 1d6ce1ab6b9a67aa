// The BVH builder's own parallel loops (the phases around Embree's build and the wide collapse), on plain
// std::thread: no dependency beyond the standard library, and a handful of threads a phase costs tens of
// microseconds, nothing beside a build of a million triangles. Results must not depend on the thread count:
// the callers give each task its own output range or reduce per-task results in task order.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

#include <sys/mman.h>
#include <unistd.h>

namespace raylab {

// The threads for `work` items, each thread worth at least `grain` of them: `requested` when not 0 (the tests
// force counts), else the hardware's threads, fewer for small work, at least 1.
inline uint32_t workerThreads(uint32_t requested, size_t work, size_t grain) {
  if (requested > 0) return requested;
  const size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<uint32_t>(std::clamp<size_t>(work / std::max<size_t>(grain, 1), 1, hardware));
}

// Runs task(i) for every i in [0, count) on up to `threads` threads (the caller's among them), each taking the
// next index not yet taken, and returns when all are done. Every task runs even when one throws; then the
// exception of the lowest index is rethrown, so that which error is reported does not depend on the timing.
template <typename Task>
void parallelFor(uint32_t threads, size_t count, const Task& task) {
  std::vector<std::exception_ptr> errors(count);
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const size_t helpers = std::min<size_t>(std::max(threads, 1u), count) - (count > 0 ? 1 : 0);
  try {
    for (size_t t = 0; t < helpers; ++t) pool.emplace_back(worker);
  } catch (const std::system_error&) {
    // No more threads to be had: the ones running (the caller's at least) take over the rest.
  }
  worker();
  for (std::thread& t : pool) t.join();
  for (std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// v.resize(n) for a large vector, its fresh pages faulted in on `threads` threads first. Most of a big
// resize's time is not its zero fill but the page faults (the kernel zeroes every page it hands out), and
// std::vector offers no way to skip the fill: MADV_POPULATE_WRITE (Linux 5.14) faults a range in, and its
// chunks go to the threads. temple-detail:10000000's 10M nodes (320 MB): the flattening took 259 and 289 ms
// with a plain resize, 116 and 117 ms with this (2-core machine); 183 and 200 against 156 and 160 ms on the
// 16-core host. Where the call fails (an older kernel: EINVAL), resize faults the pages in as before.
template <typename T>
void resizeFaultingInParallel(std::vector<T>& v, size_t n, uint32_t threads) {
#ifdef MADV_POPULATE_WRITE
  constexpr size_t kChunk = size_t(8) << 20;  // bytes a task
  if (n > v.capacity() && threads > 1 && (n - v.size()) * sizeof(T) >= 4 * kChunk) {
    v.reserve(n);
    const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
    const uintptr_t begin = (reinterpret_cast<uintptr_t>(v.data() + v.size()) + page - 1) & ~(page - 1);
    const uintptr_t end = reinterpret_cast<uintptr_t>(v.data() + n) & ~(page - 1);
    parallelFor(threads, (end - begin + kChunk - 1) / kChunk, [&](size_t i) {
      const uintptr_t from = begin + i * kChunk;
      madvise(reinterpret_cast<void*>(from), std::min<uintptr_t>(kChunk, end - from), MADV_POPULATE_WRITE);
    });
  }
#endif
  v.resize(n);
}

}  // namespace raylab
