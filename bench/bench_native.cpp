// The native benchmark: prints markdown tables of geocdt against CGAL.
// Usage: bench_native [--quick] [--targets] [--dt] [--cdt] [--cpu] [--data DIR]
//                     [--threads] [--timeout SECONDS]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench_config.h"
#include "cgal_reference.h"
#include "measurement.h"

#ifndef GEOCDT_BENCH_DATA_DIR
#define GEOCDT_BENCH_DATA_DIR "build/data"
#endif

namespace {

// The benchmark may share the machine: its load average says how far to trust wall times.
std::string loadAverage() {
  double load[3];
  if (getloadavg(load, 3) != 3) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", load[0], load[1], load[2]);
  return text;
}

const char* compiler() {
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "g++ " __VERSION__;
#else
  return "unknown";
#endif
}

void usage(const char* program) {
  std::printf(
      "usage: %s [--quick] [--targets] [--dt] [--cdt] [--threads] [--cpu] [--data DIR]\n"
      "          [--timeout SECONDS]\n"
      "  --targets  issue 9's targets only\n"
      "  --dt       Delaunay tables only\n"
      "  --cdt      constrained table only (all three when none is given)\n"
      "  --threads  1, 2 and 4 threads against each other (wall clock; only when asked)\n"
      "  --quick    fewer repetitions, no 4M run: checks that everything runs\n"
      "  --cpu      time with the process CPU clock instead of the wall clock (for a\n"
      "             machine shared with other work; the code measured is single-threaded)\n"
      "  --data     folder of the .gpl datasets (default %s)\n"
      "  --timeout  seconds allowed per measured row (default 300)\n",
      program, GEOCDT_BENCH_DATA_DIR);
}

}  // namespace

int main(int argc, char** argv) {
  bench::BenchConfig config;
  config.dataDir = GEOCDT_BENCH_DATA_DIR;
  bool targets = false, delaunay = false, constrained = false, threads = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      config.quick = true;
    } else if (arg == "--targets") {
      targets = true;
    } else if (arg == "--dt") {
      delaunay = true;
    } else if (arg == "--cdt") {
      constrained = true;
    } else if (arg == "--threads") {
      threads = true;
    } else if (arg == "--cpu") {
      bench::useProcessCpuClock(true);
    } else if (arg == "--data" && i + 1 < argc) {
      config.dataDir = argv[++i];
    } else if (arg == "--timeout" && i + 1 < argc) {
      config.timeoutSeconds = std::atoi(argv[++i]);
    } else {
      usage(argv[0]);
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  if (!targets && !delaunay && !constrained && !threads) targets = delaunay = constrained = true;
  if (config.timeoutSeconds <= 0) config.timeoutSeconds = 300;

  std::printf(
      "## geocdt native benchmark%s\n\nReference: %s. Compiler: %s. Clock: %s. "
      "Load average at start: %s.\n\n",
      config.quick ? " (--quick: fewer repetitions, not a measurement)" : "",
      bench::cgalDescription().c_str(), compiler(),
      bench::usingProcessCpuClock() ? "process CPU time" : "wall time", loadAverage().c_str());
  if (targets) bench::printTargetsTable(config);
  if (delaunay) bench::printDelaunayTables(config);
  if (constrained) bench::printConstrainedTable(config);
  if (threads) bench::printThreadsTable(config);
  std::printf("Load average at end: %s.\n", loadAverage().c_str());
  return 0;
}
