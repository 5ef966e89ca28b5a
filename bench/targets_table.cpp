// Issue 9's native targets: geocdt against CGAL's range insertion on uniform points, time per
// point as the input grows, and the heap peak per point when the input buffer is adopted.
#include <cstdio>

#include "bench_config.h"
#include "cgal_reference.h"
#include "geocdt_runs.h"
#include "markdown_table.h"
#include "point_sets.h"

namespace bench {
namespace {

struct Size {
  std::size_t points;
  int repetitions;
  int quickRepetitions;  // 0: skipped with --quick
};

struct Target {
  std::string what;
  double value;  // < 0: not measured
  double limit;
  std::string unit;  // "x" or " B"
};

std::string perPoint(double value, std::uint64_t points) {
  return fixed(value / static_cast<double>(points), 2);
}

}  // namespace

void printTargetsTable(const BenchConfig& config) {
  const std::vector<Size> sizes = {
      {250000, 9, 1}, {1000000, 7, 1}, {2000000, 5, 1}, {4000000, 3, 0}};
  MarkdownTable table({">points", ">reps", ">geocdt ms", ">ns/pt", ">flips/pt", ">steps/insert",
                       ">peak B/pt", ">CGAL ms", ">CGAL ns/pt", ">geocdt/CGAL"});
  double nsAt250k = -1, nsAt2M = -1, ratioAt1M = -1, ratioAt4M = -1;
  const geocdt::Options defaults;
  for (const Size& size : sizes) {
    const int reps = config.quick ? size.quickRepetitions : size.repetitions;
    if (reps == 0) continue;
    const std::vector<double> xy = uniformPointsMt19937(size.points, 10 + size.points / 250000);
    std::fprintf(stderr, "  targets: uniform %zu (%d repetitions)\n", size.points, reps);
    std::vector<RunOnce> engines = {
        [&](Sample& s, std::string& e) { return geocdtDelaunay(xy, defaults, s, e); }};
    if (cgalAvailable())
      engines.push_back([&](Sample& s, std::string& e) { return cgalDelaunay(xy, s, e); });
    const std::vector<Measurement> results =
        measureInterleaved(reps, config.timeoutSeconds, engines);
    const Measurement& ours = results[0];
    const Measurement theirs = cgalAvailable() ? results[1] : Measurement{};
    if (!ours.ok) {
      table.addRow({count(size.points), std::to_string(reps), std::string("FAILED: ") + ours.error,
                    "-", "-", "-", "-", "-", "-", "-"});
      continue;
    }
    const Sample& s = ours.median;
    const double ns = 1e9 * s.pointSeconds / static_cast<double>(size.points);
    const double r = theirs.ok ? s.pointSeconds / theirs.median.pointSeconds : -1;
    if (size.points == 250000) nsAt250k = ns;
    if (size.points == 2000000) nsAt2M = ns;
    if (size.points == 1000000) ratioAt1M = r;
    if (size.points == 4000000) ratioAt4M = r;
    table.addRow(
        {count(size.points), std::to_string(reps), milliseconds(s.pointSeconds), fixed(ns, 0),
         perPoint(static_cast<double>(s.flips), size.points),
         perPoint(static_cast<double>(s.walkSteps), s.locates ? s.locates : 1),
         perPoint(static_cast<double>(s.peakBytes), size.points),
         theirs.ok ? milliseconds(theirs.median.pointSeconds) : "-",
         theirs.ok ? fixed(1e9 * theirs.median.pointSeconds / static_cast<double>(size.points), 0)
                   : "-",
         theirs.ok ? ratio(s.pointSeconds, theirs.median.pointSeconds) : "-"});
  }

  // The wasm binding's memory: the input buffer (counted) adopted by the core, then released.
  const std::size_t adoptedPoints = 1000000;
  const std::vector<double> xy = uniformPointsMt19937(adoptedPoints, 14);
  std::fprintf(stderr, "  targets: adopted buffer, uniform %zu\n", adoptedPoints);
  const Measurement adopted = measure(1, config.timeoutSeconds, [&](Sample& s, std::string& e) {
    return geocdtDelaunayAdopted(xy, s, e);
  });
  const double adoptedBytes =
      adopted.ok ? static_cast<double>(adopted.median.peakBytes) / adoptedPoints : -1;

  const std::vector<Target> targets = {
      {"1M uniform points, geocdt / CGAL range insertion", ratioAt1M, 0.7, "x"},
      {"4M uniform points, geocdt / CGAL range insertion", ratioAt4M, 0.7, "x"},
      {"time per point at 2M / at 250k uniform points",
       nsAt250k > 0 && nsAt2M > 0 ? nsAt2M / nsAt250k : -1, 1.15, "x"},
      {"heap peak per point, 1M uniform, input buffer adopted and mesh released", adoptedBytes, 80,
       " B"},
  };
  MarkdownTable verdicts({"target", ">value", ">limit", "met"});
  for (const Target& t : targets) {
    const int decimals = t.unit == "x" ? 2 : 1;
    verdicts.addRow({t.what, t.value < 0 ? "-" : fixed(t.value, decimals) + t.unit,
                     "<= " + fixed(t.limit, decimals) + t.unit,
                     t.value < 0 ? "not measured" : (t.value <= t.limit ? "met" : "MISSED")});
  }
  std::printf(
      "### Targets: uniform points, geocdt (default options) vs CGAL Delaunay_triangulation_2\n\n"
      "Medians; peak B/pt is the peak extra heap of one build per point (the input not "
      "counted). The adopted-buffer row counts the input buffer too: it is what the wasm heap "
      "holds.\n\n%s\n%s\n",
      table.str().c_str(), verdicts.str().c_str());
}

}  // namespace bench
