#pragma once
// Command-line settings shared by the benchmark tables.
#include <string>

namespace bench {

struct BenchConfig {
  bool quick = false;        // fewer repetitions and no 4M run: a smoke test, not a measurement
  std::string dataDir;       // where scripts/datasets wrote the .gpl files
  int timeoutSeconds = 300;  // per measured row; a hang becomes a failed row
};

// Issue 2's tables: Delaunay triangulation of point sets, geocdt against CGAL, and geocdt's
// insertion order x locate start combinations.
void printDelaunayTables(const BenchConfig& config);

// Issue 9's native targets, each printed with its value, limit and whether it is met.
void printTargetsTable(const BenchConfig& config);

// Issue 3's table: constrained triangulation of real and random polylines.
void printConstrainedTable(const BenchConfig& config);

// Issue 13's table: 1, 2 and 4 threads against each other (wall clock).
void printThreadsTable(const BenchConfig& config);

}  // namespace bench
