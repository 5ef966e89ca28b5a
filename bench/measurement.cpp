#include "measurement.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>

namespace bench {
namespace {

bool processCpuClock = false;

std::uint64_t wallNanos() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

// What a child process sends back: one sample, or why there is none.
struct Outcome {
  bool ok = false;
  char error[240] = {};
  Sample sample;
};

void setError(char (&out)[240], const std::string& text) {
  std::snprintf(out, sizeof out, "%s", text.c_str());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Reads exactly size bytes unless the deadline passes or the writer goes away.
bool readWithDeadline(int fd, char* out, std::size_t size, std::uint64_t deadlineNanos) {
  std::size_t got = 0;
  while (got < size) {
    const std::uint64_t now = wallNanos();
    if (now >= deadlineNanos) return false;
    pollfd p{fd, POLLIN, 0};
    const int waitMs =
        static_cast<int>(std::min<std::uint64_t>((deadlineNanos - now) / 1000000 + 1, 1000));
    const int ready = poll(&p, 1, waitMs);
    if (ready < 0 && errno != EINTR) return false;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, out + got, size - got);
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

Outcome runInChild(const RunOnce& once) {
  Outcome outcome;
  try {
    std::string error;
    outcome.ok = once(outcome.sample, error);
    if (!outcome.ok) setError(outcome.error, error.empty() ? "failed" : error);
  } catch (const std::exception& e) {
    setError(outcome.error, std::string("exception: ") + e.what());
  } catch (...) {
    setError(outcome.error, "unknown exception");
  }
  return outcome;
}

Outcome runIsolated(int timeoutSeconds, const RunOnce& once) {
  Outcome outcome;
  int fds[2];
  if (pipe(fds) != 0) {
    setError(outcome.error, "pipe() failed");
    return outcome;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]);
    close(fds[1]);
    setError(outcome.error, "fork() failed");
    return outcome;
  }
  if (child == 0) {
    close(fds[0]);
    const Outcome result = runInChild(once);
    const char* bytes = reinterpret_cast<const char*>(&result);
    std::size_t sent = 0;
    while (sent < sizeof result) {
      const ssize_t n = write(fds[1], bytes + sent, sizeof result - sent);
      if (n <= 0) break;
      sent += static_cast<std::size_t>(n);
    }
    _exit(0);  // skip the destructors and atexit handlers of the parent's state
  }
  close(fds[1]);
  const std::uint64_t deadline =
      wallNanos() + static_cast<std::uint64_t>(timeoutSeconds) * 1000000000ull;
  const bool received =
      readWithDeadline(fds[0], reinterpret_cast<char*>(&outcome), sizeof outcome, deadline);
  close(fds[0]);
  const bool timedOut = !received && wallNanos() >= deadline;
  if (!received) kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  if (received) return outcome;
  outcome = Outcome{};
  if (timedOut) {
    setError(outcome.error, "timed out after " + std::to_string(timeoutSeconds) + " s");
  } else if (WIFSIGNALED(status)) {
    setError(outcome.error, std::string("crashed: ") + strsignal(WTERMSIG(status)));
  } else {
    setError(outcome.error,
             "exited without a result (status " + std::to_string(WEXITSTATUS(status)) + ")");
  }
  return outcome;
}

}  // namespace

void useProcessCpuClock(bool enable) { processCpuClock = enable; }
bool usingProcessCpuClock() { return processCpuClock; }

std::uint64_t nowNanos() {
  if (!processCpuClock) return wallNanos();
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<std::uint64_t>(t.tv_sec) * 1000000000ull +
         static_cast<std::uint64_t>(t.tv_nsec);
}

double secondsSince(std::uint64_t startNanos) {
  return 1e-9 * static_cast<double>(nowNanos() - startNanos);
}

std::vector<Measurement> measureInterleaved(int repetitions, int timeoutSeconds,
                                            const std::vector<RunOnce>& engines) {
  std::vector<Measurement> results(engines.size());
  std::vector<std::vector<Sample>> samples(engines.size());
  std::vector<bool> failed(engines.size(), false);
  for (int r = 0; r < repetitions; ++r) {
    for (std::size_t e = 0; e < engines.size(); ++e) {
      if (failed[e]) continue;
      const Outcome outcome = runIsolated(timeoutSeconds, engines[e]);
      if (!outcome.ok) {
        failed[e] = true;
        std::memcpy(results[e].error, outcome.error, sizeof outcome.error);
        continue;
      }
      samples[e].push_back(outcome.sample);
    }
  }
  for (std::size_t e = 0; e < engines.size(); ++e) {
    Measurement& m = results[e];
    if (failed[e]) continue;
    m.ok = true;
    m.repetitions = repetitions;
    m.median = samples[e].front();
    std::vector<double> points, edges, extra;
    for (const Sample& s : samples[e]) {
      points.push_back(s.pointSeconds);
      edges.push_back(s.edgeSeconds);
      extra.push_back(s.extraSeconds);
    }
    m.median.pointSeconds = median(points);
    m.median.edgeSeconds = median(edges);
    m.median.extraSeconds = median(extra);
  }
  return results;
}

Measurement measure(int repetitions, int timeoutSeconds, const RunOnce& once) {
  return measureInterleaved(repetitions, timeoutSeconds, {once}).front();
}

}  // namespace bench
