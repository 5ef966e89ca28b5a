// Issue 3's benchmark: constrained triangulation of real polylines and random crossing
// segments, geocdt against CGAL's Constrained_Delaunay_triangulation_2, with the time split
// of the paper's Table I and a check of every result for flipped and zero-area triangles.
#include <cstdio>

#include "bench_config.h"
#include "cgal_reference.h"
#include "geocdt_runs.h"
#include "markdown_table.h"
#include "point_sets.h"

namespace bench {
namespace {

struct PolylineCase {
  std::string name;
  std::vector<double> freePoints;  // inserted before the polylines
  geocdt::testing::PolylineSet polylines;
  std::string missing;  // why the case could not be loaded, if it could not
};

PolylineCase fileCase(const BenchConfig& config, const std::string& name, const std::string& file,
                      const std::string& howToMake) {
  PolylineCase c{name, {}, {}, {}};
  const std::string path = config.dataDir + "/" + file;
  const std::string error = geocdt::testing::readPolylineFile(path, c.polylines);
  if (!error.empty()) c.missing = error + " (make it with " + howToMake + ")";
  return c;
}

std::string status(const Measurement& m, const Sample& s) {
  if (!m.ok) return std::string("FAILED: ") + m.error;
  if (s.flipped || s.zeroArea) return "INVALID output";
  return "ok";
}

}  // namespace

void printConstrainedTable(const BenchConfig& config) {
  const std::string naturalEarth = "node scripts/datasets/natural_earth.mjs";
  std::vector<PolylineCase> cases;
  cases.push_back(fileCase(config, "Natural Earth 10m rings", "ne_10m_rings.gpl", naturalEarth));
  cases.push_back(fileCase(config, "Natural Earth 10m arcs", "ne_10m_arcs.gpl", naturalEarth));
  cases.push_back({"1,000 random segments + 100k points",
                   uniformPointsMt19937(100000, 8),
                   randomSegments(1000, 9),
                   {}});
  const std::string gshhg = "scripts/datasets/all.sh";
  cases.push_back(fileCase(config, "GSHHG Europe", "gshhg_region.gpl", gshhg));
  cases.push_back(fileCase(config, "GSHHG Asia", "gshhg_asia.gpl", gshhg));

  const int reps = config.quick ? 1 : 3;
  MarkdownTable table({"dataset", "engine", ">points", ">segments", ">insert points ms",
                       ">insert edges ms", ">total ms", ">crossings found", ">steps/locate",
                       ">flips/pt", ">triangles", ">flipped", ">zero-area", ">peak MB",
                       ">total vs CGAL Epick", "result"});
  std::vector<std::string> notes;
  for (const PolylineCase& c : cases) {
    if (!c.missing.empty()) {
      notes.push_back("skipped " + c.name + ": " + c.missing);
      continue;
    }
    const std::size_t points = c.freePoints.size() / 2 + c.polylines.pointCount();
    const std::string segments = count(c.polylines.segmentCount());
    struct Engine {
      const char* name;
      bool split;  // whether points and edges are timed as separate phases
      RunOnce once;
    };
    std::vector<Engine> engines;
    if (cgalAvailable()) {
      engines.push_back({"CGAL Epick", true, [&](Sample& s, std::string& e) {
                           return cgalConstrained(c.freePoints, c.polylines, CgalKernel::Inexact, s,
                                                  e);
                         }});
    }
    engines.push_back({"geocdt", true, [&](Sample& s, std::string& e) {
                         return geocdtConstrained(c.freePoints, c.polylines,
                                                  ConstrainedCalls::PointsThenPolylines, s, e);
                       }});
    engines.push_back({"geocdt one call", false, [&](Sample& s, std::string& e) {
                         return geocdtConstrained(c.freePoints, c.polylines,
                                                  ConstrainedCalls::OneCall, s, e);
                       }});
    // The same points with no constraints: what the constraints cost on top of them.
    std::vector<double> allPoints = c.freePoints;
    allPoints.insert(allPoints.end(), c.polylines.xy.begin(), c.polylines.xy.end());
    engines.push_back({"geocdt points alone", false, [&](Sample& s, std::string& e) {
                         return geocdtDelaunay(allPoints, geocdt::Options(), s, e);
                       }});
    std::fprintf(stderr, "  constrained: %s (%d repetitions)\n", c.name.c_str(), reps);
    std::vector<RunOnce> runs;
    for (const Engine& engine : engines) runs.push_back(engine.once);
    std::vector<Measurement> results = measureInterleaved(reps, config.timeoutSeconds, runs);
    if (cgalAvailable()) {
      // The exact kernel is here for its validity, not its speed: one run keeps the bench short.
      engines.push_back({"CGAL Epeck (1 run)", true, [&](Sample& s, std::string& e) {
                           return cgalConstrained(c.freePoints, c.polylines, CgalKernel::Exact, s,
                                                  e);
                         }});
      results.push_back(measure(1, config.timeoutSeconds, engines.back().once));
    }
    const bool haveReference = cgalAvailable() && results[0].ok;
    for (std::size_t i = 0; i < engines.size(); ++i) {
      const Measurement& m = results[i];
      const Sample& s = m.median;
      auto cell = [&](const std::string& text) { return m.ok ? text : std::string("-"); };
      auto phase = [&](double seconds) {
        return engines[i].split ? cell(milliseconds(seconds)) : "-";
      };
      // Walk and flip figures only where they describe the whole run.
      const bool geocdtWhole = std::string(engines[i].name).rfind("geocdt ", 0) == 0;
      auto per = [&](std::uint64_t what, std::uint64_t of) {
        return geocdtWhole && of ? cell(fixed(static_cast<double>(what) / of, 2)) : "-";
      };
      table.addRow(
          {c.name, engines[i].name, count(points), segments, phase(s.pointSeconds),
           phase(s.edgeSeconds), cell(milliseconds(s.totalSeconds())), cell(count(s.crossings)),
           per(s.walkSteps, s.locates), per(s.flips, points), cell(count(s.triangles)),
           cell(count(s.flipped)), cell(count(s.zeroArea)),
           cell(fixed(1e-6 * static_cast<double>(s.peakBytes), 0)),
           m.ok && haveReference ? ratio(s.totalSeconds(), results[0].median.totalSeconds()) : "-",
           status(m, s)});
    }
  }
  std::printf(
      "### Constrained triangulation: geocdt vs CGAL Constrained_Delaunay_triangulation_2 "
      "(Exact_predicates_tag)\n\n"
      "Medians of %d repetitions. geocdt: insertPoints of all points, then insertPolylines "
      "(which finds the points again); geocdt one call: insertPolylines alone (after "
      "insertPoints of the free points); geocdt points alone: insertPoints of the same points, "
      "no constraints. Steps/locate: triangles visited per point location (segment ends "
      "are not located); flips/pt: flips per input point, both for the one-call and "
      "points-alone runs. Crossings found: vertices added by the edge phase. "
      "Flipped "
      "and zero-area: triangles of the output, on its double coordinates, by exact "
      "orientation. Peak MB: peak extra heap through operator new (GMP's own allocations in "
      "Epeck are not counted).\n\n%s\n",
      reps, table.str().c_str());
  for (const std::string& note : notes) std::printf("- %s\n", note.c_str());
  if (!notes.empty()) std::printf("\n");
}

}  // namespace bench
