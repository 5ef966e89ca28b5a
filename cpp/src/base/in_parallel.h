#pragma once
// Jobs on several threads (Options::threads), for the builds that have them (GEOCDT_THREADS);
// without, every job runs on the calling thread.
#include <cstdint>
#include <vector>

#ifdef GEOCDT_THREADS
#include <exception>
#include <system_error>
#include <thread>
#endif

#include "base/chunks.h"

namespace geocdt {

// Runs job(i) for i in [0, n): job(0) on the calling thread, the others on threads of their
// own, or on the calling thread too where no thread can be started (a build without them, a
// pool of workers used up). An exception in a job is caught there and rethrown here once all
// have ended. Returns the threads that ran the jobs, the calling one included.
template <typename Job>
std::uint32_t inParallel(std::uint32_t n, Job job) {
#ifdef GEOCDT_THREADS
  std::vector<std::exception_ptr> failed(n);
  const auto run = [&](std::uint32_t i) {
    try {
      job(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  std::vector<std::uint32_t> inline_;
  for (std::uint32_t i = 1; i < n; ++i) {
    try {
      threads.emplace_back(run, i);
    } catch (const std::system_error&) {
      inline_.push_back(i);
    }
  }
  if (n > 0) run(0);
  for (const std::uint32_t i : inline_) run(i);
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return static_cast<std::uint32_t>(threads.size()) + 1;
#else
  for (std::uint32_t i = 0; i < n; ++i) job(i);
  return 1;
#endif
}

// Whether this build runs threads at all: where not, the branches that would split work are
// left out.
#ifdef GEOCDT_THREADS
inline constexpr bool kThreadsBuilt = true;
#else
inline constexpr bool kThreadsBuilt = false;
#endif

// Below this many indices a loop is not worth a thread.
inline constexpr std::size_t kParallelLoop = std::size_t{1} << 16;

// forChunks over [first, last), cut into `threads` consecutive ranges run side by side (one
// range on one thread where the loop is short). body must touch only what its indices own.
template <typename Body>
void forChunksOn(std::uint32_t threads, std::size_t first, std::size_t last, Body body) {
  if constexpr (kThreadsBuilt) {
    if (threads > 1 && last - first >= kParallelLoop) {
      const std::size_t n = last - first;
      inParallel(threads, [&](std::uint32_t i) {
        forChunks(first + n * i / threads, first + n * (i + 1) / threads, body);
      });
      return;
    }
  }
  (void)threads;
  forChunks(first, last, body);
}

}  // namespace geocdt
