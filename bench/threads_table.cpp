// Issue 13's native targets: Options::threads at 1, 2 and 4 threads on uniform points and on
// constrained real data (the points go in strips; the constraints follow on one thread), each
// against one thread in the same interleaved rounds. Always timed by the wall clock: the
// process CPU clock adds up the threads.
#include <cstdio>
#include <string>

#include "bench_config.h"
#include "geocdt_runs.h"
#include "markdown_table.h"
#include "point_sets.h"

namespace bench {
namespace {

struct ThreadsCase {
  std::string name;
  std::vector<double> points;              // uniform points, or empty
  geocdt::testing::PolylineSet polylines;  // real data, or empty
  std::string missing;
  int repetitions;
};

geocdt::Options withThreads(std::uint32_t threads) {
  geocdt::Options options;
  options.threads = threads;
  return options;
}

}  // namespace

void printThreadsTable(const BenchConfig& config) {
  const bool cpuClock = usingProcessCpuClock();
  useProcessCpuClock(false);
  std::vector<ThreadsCase> cases;
  cases.push_back({"uniform 1M", uniformPointsMt19937(1000000, 21), {}, {}, config.quick ? 1 : 7});
  if (!config.quick) cases.push_back({"uniform 4M", uniformPointsMt19937(4000000, 22), {}, {}, 5});
  for (const auto& [name, file] : std::vector<std::pair<std::string, std::string>>{
           {"Natural Earth 10m rings", "ne_10m_rings.gpl"}, {"GSHHG Asia", "gshhg_asia.gpl"}}) {
    ThreadsCase c{name, {}, {}, {}, config.quick ? 1 : 5};
    const std::string error =
        geocdt::testing::readPolylineFile(config.dataDir + "/" + file, c.polylines);
    if (!error.empty()) c.missing = error + " (make it with scripts/datasets/all.sh)";
    cases.push_back(c);
  }

  const std::vector<std::uint32_t> threadCounts = {1, 2, 4};
  MarkdownTable table({"input", ">threads", ">points ms", ">constraints ms", ">total ms",
                       ">/ 1 thread", ">peak B/pt", ">peak / 1 thread", ">steps/locate"});
  std::vector<std::string> notes;
  for (const ThreadsCase& c : cases) {
    if (!c.missing.empty()) {
      notes.push_back("skipped " + c.name + ": " + c.missing);
      continue;
    }
    std::fprintf(stderr, "  threads: %s (%d repetitions)\n", c.name.c_str(), c.repetitions);
    std::vector<RunOnce> engines;
    for (const std::uint32_t threads : threadCounts) {
      const geocdt::Options options = withThreads(threads);
      if (c.points.empty()) {
        engines.push_back([&c, options](Sample& s, std::string& e) {
          return geocdtConstrained({}, c.polylines, ConstrainedCalls::OneCall, s, e, options);
        });
      } else {
        engines.push_back([&c, options](Sample& s, std::string& e) {
          return geocdtDelaunay(c.points, options, s, e);
        });
      }
    }
    const std::vector<Measurement> results =
        measureInterleaved(c.repetitions, config.timeoutSeconds, engines);
    const std::size_t points = c.points.empty() ? c.polylines.pointCount() : c.points.size() / 2;
    for (std::size_t i = 0; i < threadCounts.size(); ++i) {
      const Measurement& m = results[i];
      if (!m.ok) {
        table.addRow({c.name, std::to_string(threadCounts[i]), std::string("FAILED: ") + m.error,
                      "-", "-", "-", "-", "-", "-"});
        continue;
      }
      const Sample& s = m.median;
      const Sample& one = results[0].median;
      const bool oneOk = results[0].ok;
      table.addRow(
          {c.name, std::to_string(threadCounts[i]), milliseconds(s.pointSeconds),
           c.points.empty() ? milliseconds(s.edgeSeconds) : "-", milliseconds(s.totalSeconds()),
           oneOk ? ratio(s.totalSeconds(), one.totalSeconds()) : "-",
           fixed(static_cast<double>(s.peakBytes) / static_cast<double>(points), 1),
           oneOk ? ratio(static_cast<double>(s.peakBytes), static_cast<double>(one.peakBytes))
                 : "-",
           fixed(static_cast<double>(s.walkSteps) / static_cast<double>(s.locates ? s.locates : 1),
                 2)});
    }
  }
  useProcessCpuClock(cpuClock);
  std::printf(
      "### Threads: geocdt on 1, 2 and 4 threads (Options::threads)\n\n"
      "Wall-clock medians of interleaved rounds; \"/ 1 thread\" is the total against one "
      "thread's in the same rounds. Peak B/pt: the peak extra heap of one run per input point "
      "(the input not counted). Targets on 2 threads: uniform 4M <= 0.6x, constrained real data "
      "<= 0.75x, peak <= 1.15x.\n\n%s\n",
      table.str().c_str());
  for (const std::string& note : notes) std::printf("- %s\n", note.c_str());
  if (!notes.empty()) std::printf("\n");
}

}  // namespace bench
