// The benchmark without CGAL: no reference runs, and geocdt's own exact orientation
// checks triangles.
#include "cgal_reference.h"
#include "geocdt/predicates.h"

namespace bench {

bool cgalAvailable() { return false; }
std::string cgalDescription() {
  return "CGAL was not found at build time: no reference columns (Debian: apt-get install "
         "libcgal-dev)";
}

bool cgalDelaunay(const std::vector<double>&, Sample&, std::string& error) {
  error = "CGAL was not found at build time";
  return false;
}

bool cgalConstrained(const std::vector<double>&, const geocdt::testing::PolylineSet&, CgalKernel,
                     Sample&, std::string& error) {
  error = "CGAL was not found at build time";
  return false;
}

void countBadTriangles(const std::vector<double>& xy, const std::vector<std::uint32_t>& triangles,
                       Sample& sample) {
  sample.flipped = sample.zeroArea = 0;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const double* a = &xy[2 * triangles[t]];
    const double* b = &xy[2 * triangles[t + 1]];
    const double* c = &xy[2 * triangles[t + 2]];
    const geocdt::Sign s = geocdt::orient2d(a[0], a[1], b[0], b[1], c[0], c[1]);
    if (s == geocdt::Sign::Negative) ++sample.flipped;
    if (s == geocdt::Sign::Zero) ++sample.zeroArea;
  }
}

}  // namespace bench
