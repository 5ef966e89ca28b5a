// Issue 2's benchmark: geocdt's Delaunay triangulation against CGAL's on synthetic inputs,
// then geocdt's insertion order and locate start options on 1M uniform points.
#include <algorithm>
#include <cstdio>
#include <functional>

#include "bench_config.h"
#include "cgal_reference.h"
#include "geocdt_runs.h"
#include "markdown_table.h"
#include "point_generators.h"
#include "point_sets.h"

namespace bench {
namespace {

struct PointCase {
  const char* name;
  std::function<std::vector<double>()> make;
  int repetitions;
  int quickRepetitions;  // 0: skipped with --quick
};

std::string bytesPerPoint(const Measurement& m, std::size_t points) {
  return m.ok ? fixed(static_cast<double>(m.median.peakBytes) / static_cast<double>(points), 1)
              : "-";
}

std::string failure(const Measurement& m) { return std::string("FAILED: ") + m.error; }

std::string stepsPer(std::uint64_t steps, std::uint64_t locates) {
  return locates ? fixed(static_cast<double>(steps) / static_cast<double>(locates), 2) : "-";
}

void printComparison(const BenchConfig& config) {
  const std::vector<PointCase> cases = {
      {"uniform 10k", [] { return uniformPointsMt19937(10000, 1); }, 15, 5},
      {"uniform 100k", [] { return uniformPointsMt19937(100000, 2); }, 9, 3},
      {"uniform 1M", [] { return uniformPointsMt19937(1000000, 3); }, 5, 1},
      {"uniform 4M", [] { return uniformPointsMt19937(4000000, 4); }, 3, 0},
      {"gaussian clusters 1M", [] { return clustersOfManySpreads(1000000, 5); }, 5, 1},
      {"lattice 1000x1000", [] { return geocdt::testing::latticePoints(1000); }, 5, 1},
  };
  MarkdownTable table({"input", ">points", ">reps", ">geocdt ms", ">Mpt/s", ">ns/pt",
                       ">steps/insert", ">peak B/pt", ">CGAL ms", ">CGAL Mpt/s", ">CGAL peak B/pt",
                       ">geocdt/CGAL", "same triangle count"});
  const geocdt::Options defaults;
  for (const PointCase& c : cases) {
    const int reps = config.quick ? c.quickRepetitions : c.repetitions;
    if (reps == 0) continue;
    const std::vector<double> xy = c.make();
    const std::size_t n = xy.size() / 2;
    std::fprintf(stderr, "  delaunay: %s (%d repetitions)\n", c.name, reps);
    std::vector<RunOnce> engines = {
        [&](Sample& s, std::string& e) { return geocdtDelaunay(xy, defaults, s, e); }};
    if (cgalAvailable()) {
      engines.push_back([&](Sample& s, std::string& e) { return cgalDelaunay(xy, s, e); });
    }
    const std::vector<Measurement> results =
        measureInterleaved(reps, config.timeoutSeconds, engines);
    const Measurement& ours = results[0];
    const Measurement theirs = cgalAvailable() ? results[1] : Measurement{};
    const double t = ours.median.pointSeconds;
    const double ct = theirs.median.pointSeconds;
    std::string same = "-";
    if (ours.ok && theirs.ok) {
      same = ours.median.triangles == theirs.median.triangles
                 ? "yes"
                 : "NO: " + count(ours.median.triangles) + " vs " + count(theirs.median.triangles);
    }
    const std::string steps = ours.ok ? stepsPer(ours.median.walkSteps, ours.median.locates) : "-";
    table.addRow({c.name, count(n), std::to_string(reps), ours.ok ? milliseconds(t) : failure(ours),
                  ours.ok ? millionsPerSecond(n, t) : "-",
                  ours.ok ? fixed(1e9 * t / static_cast<double>(n), 0) : "-", steps,
                  bytesPerPoint(ours, n),
                  theirs.ok ? milliseconds(ct) : (cgalAvailable() ? failure(theirs) : "-"),
                  theirs.ok ? millionsPerSecond(n, ct) : "-", bytesPerPoint(theirs, n),
                  ours.ok && theirs.ok ? ratio(t, ct) : "-", same});
  }
  std::printf(
      "### Delaunay triangulation: geocdt (default options) vs CGAL Delaunay_triangulation_2\n\n"
      "Times are medians; peak B/pt is the peak extra heap of one build per point.\n\n%s\n",
      table.str().c_str());
}

const char* orderName(geocdt::InsertionOrder order) {
  switch (order) {
    case geocdt::InsertionOrder::Input: return "Input";
    case geocdt::InsertionOrder::Hilbert: return "Hilbert";
    case geocdt::InsertionOrder::Brio: return "Brio";
  }
  return "?";
}

void printOptionComparison(const BenchConfig& config) {
  const std::vector<double> xy = uniformPointsMt19937(1000000, 3);
  const std::vector<double> late = uniformPointsMt19937(100000, 6);
  const std::vector<double> queries = uniformPointsMt19937(10000, 7);
  const int reps = config.quick ? 1 : 3;
  // Some combinations walk O(sqrt n) per point; a short limit keeps the whole bench short.
  const int timeout = std::min(config.timeoutSeconds, config.quick ? 20 : 30);
  MarkdownTable table({"order", "start", ">build 1M ms", ">Mpt/s", ">steps/insert",
                       ">then insert 100k ms", ">late steps/insert", ">then locate 10k ms"});
  for (auto order : {geocdt::InsertionOrder::Input, geocdt::InsertionOrder::Hilbert,
                     geocdt::InsertionOrder::Brio}) {
    for (auto start : {geocdt::LocateStart::Grid, geocdt::LocateStart::LastTriangle}) {
      geocdt::Options options;
      options.order = order;
      options.start = start;
      const char* startName = start == geocdt::LocateStart::Grid ? "Grid" : "LastTriangle";
      std::fprintf(stderr, "  options: %s + %s (%d repetitions)\n", orderName(order), startName,
                   reps);
      const Measurement m = measure(reps, timeout, [&](Sample& s, std::string& e) {
        return geocdtDelaunayThenLate(xy, late, queries, options, s, e);
      });
      const Sample& s = m.median;
      if (!m.ok) {
        table.addRow({orderName(order), startName, failure(m), "-", "-", "-", "-", "-"});
        continue;
      }
      table.addRow({orderName(order), startName, milliseconds(s.pointSeconds),
                    millionsPerSecond(1000000, s.pointSeconds), stepsPer(s.walkSteps, s.locates),
                    milliseconds(s.edgeSeconds), stepsPer(s.lateWalkSteps, s.lateLocates),
                    milliseconds(s.extraSeconds)});
    }
  }
  std::printf(
      "### geocdt options on 1M uniform points (%d repetitions, medians, %d s limit)\n\n"
      "Build: one insertPoints call. Then 100k more uniform points in one more insertPoints "
      "call, then 10k locate() queries at uniform points.\n\n%s\n",
      reps, timeout, table.str().c_str());
}

}  // namespace

void printDelaunayTables(const BenchConfig& config) {
  printComparison(config);
  printOptionComparison(config);
}

}  // namespace bench
