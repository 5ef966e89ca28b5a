#pragma once
// What one benchmark run measures, and the summary of several repetitions.
// Plain data only: results cross a pipe from the child process that ran them.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace bench {

struct Sample {
  double pointSeconds = 0;      // building the triangulation of the points
  double edgeSeconds = 0;       // inserting the constraint segments (0 without constraints)
  double extraSeconds = 0;      // a follow-up phase some runs time (late inserts, queries)
  std::uint64_t peakBytes = 0;  // peak extra heap during the run
  std::uint64_t walkSteps = 0;
  std::uint64_t locates = 0;
  std::uint64_t flips = 0;
  std::uint64_t lateWalkSteps = 0;  // the same for the follow-up phase
  std::uint64_t lateLocates = 0;
  std::uint64_t crossings = 0;  // vertices added where constraints cross
  std::uint64_t vertices = 0;
  std::uint64_t triangles = 0;
  std::uint64_t flipped = 0;   // clockwise triangles, by exact orientation
  std::uint64_t zeroArea = 0;  // collinear triangles, by exact orientation

  double totalSeconds() const { return pointSeconds + edgeSeconds; }
};

struct Measurement {
  bool ok = false;
  char error[240] = {};  // why the run failed: an error status, a crash, a timeout
  int repetitions = 0;
  // Times are medians over the repetitions; the rest comes from the first repetition.
  Sample median;
};

// One repetition: fills the sample, or returns false with an error message.
using RunOnce = std::function<bool(Sample&, std::string&)>;

// Measures several engines on the same input: repetition r of every engine runs before
// repetition r + 1 of any, so that load from other processes falls on all of them alike.
// Each repetition runs in a forked child process, so that a crash, a failed assertion or a
// hang (past timeoutSeconds) of the code under test becomes a failed measurement instead
// of the end of the benchmark. An engine stops at its first failure.
std::vector<Measurement> measureInterleaved(int repetitions, int timeoutSeconds,
                                            const std::vector<RunOnce>& engines);
Measurement measure(int repetitions, int timeoutSeconds, const RunOnce& once);

// The clock of every timed phase: wall time by default; the process's CPU time (user +
// system) on request, which other processes on a shared machine disturb less.
void useProcessCpuClock(bool enable);
bool usingProcessCpuClock();
double secondsSince(std::uint64_t startNanos);
std::uint64_t nowNanos();

}  // namespace bench
