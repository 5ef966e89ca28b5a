// libFuzzer target: arbitrary bytes as a sequence of edits of one Triangulation (insert
// points, insert a polyline, remove a point, remove a polyline, move a point or a polyline
// vertex, or nudge one an eighth of the way to a point, refine), each followed by both
// halves of the invariant checker against what remains. Bad ids and coordinates are tried
// too: they must be refused and change nothing.
//
// Input: byte 0 = options (see decodeOptions), then a PointDecoder header, then operations
// until the bytes run out: an operation byte (low 3 bits: which; the rest: a count or an
// index), then its points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "edit_model.h"
#include "fuzz_input.h"
#include "geocdt/triangulation.h"

namespace geocdt::fuzz {
namespace {

constexpr std::size_t kMaxOperations = 48;
constexpr std::size_t kMaxPoints = 256;

bool valid(double x, double y) { return validCoordinate(x) && validCoordinate(y); }

// " (n points)", or with all, the points themselves.
std::string listed(const std::vector<double>& xy, bool all) {
  if (!all) return " (" + std::to_string(xy.size() / 2) + " points)";
  std::string out;
  char buffer[64];
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    std::snprintf(buffer, sizeof buffer, " %.17g,%.17g", xy[i], xy[i + 1]);
    out += buffer;
  }
  return out;
}

void require(const Status& s, const std::string& what) {
  if (!s.ok()) fail(what + " returned an error: " + s.message);
}

// The vertex count and the mesh must not change when a call is refused.
void requireRefused(const Status& s, const Triangulation& t, std::size_t vertices,
                    std::size_t triangles, const std::string& what) {
  if (s.ok()) fail(what + " was accepted");
  if (t.vertexCount() != vertices || t.triangleCount() != triangles)
    fail(what + " was refused but changed the triangulation");
}

// The operations are decoded as they run (each one's arguments depend on what is there):
// the input is the bytes, and GEOCDT_FUZZ_PRINT=1 prints each operation as it runs.
struct Input {
  std::vector<std::uint8_t> bytes;
};

Input decode(const std::uint8_t* data, std::size_t size) { return {{data, data + size}}; }

void print(const Input& input) {
  std::fprintf(stderr, "fuzz_edits: %zu bytes, operations follow\n", input.bytes.size());
}

void run(const Input& input) {
  ByteReader in(input.bytes.data(), input.bytes.size());
  const Options options = decodeOptions(in.byte());
  PointDecoder decoder(in);
  const bool verbose = printRequested();
  Triangulation t(options);
  testing::EditModel model;
  std::size_t points = 0;
  double x = 0, y = 0;
  for (std::size_t op = 0; op < kMaxOperations && in.remaining() > 0; ++op) {
    const std::uint8_t b = in.byte();
    const std::size_t arg = b >> 3;
    const std::vector<std::uint32_t> ids = model.pointIds();
    const std::vector<std::size_t> lines = model.polylineNumbers();
    std::string what;
    switch (b & 7) {
      case 0:
      case 1: {  // insert points
        std::vector<double> xy;
        for (std::size_t k = 0; k <= arg % 8 && points < kMaxPoints; ++k, ++points) {
          decoder.next(in, x, y);
          if (!valid(x, y)) continue;
          xy.insert(xy.end(), {x, y});
        }
        what = "insertPoints" + listed(xy, verbose);
        require(model.insertPoints(t, xy), what);
        break;
      }
      case 2: {  // insert a polyline, a ring when bit 3 is set
        std::vector<double> line;
        for (std::size_t k = 0; k <= 1 + (arg >> 1) % 6 && points < kMaxPoints; ++k, ++points) {
          decoder.next(in, x, y);
          if (valid(x, y)) line.insert(line.end(), {x, y});
        }
        if ((arg & 1) && line.size() >= 4) line.insert(line.end(), {line[0], line[1]});
        what = "insertPolyline" + listed(line, verbose);
        require(model.insertPolyline(t, line), what);
        break;
      }
      case 3: {  // remove a point; with bit 4 of arg, every few points in one call
        if (ids.empty()) break;
        if (!(arg & 16)) {
          const std::uint32_t id = ids[arg % ids.size()];
          what = "removePoint " + std::to_string(id);
          require(model.removePoint(t, id), what);
          break;
        }
        std::vector<std::uint32_t> batch;
        const std::size_t step = 1 + arg % 4;
        for (std::size_t i = arg % step; i < ids.size(); i += step) batch.push_back(ids[i]);
        if (batch.empty()) break;
        if (arg & 8) {  // one of them twice: refused, nothing changed
          batch.push_back(batch.front());
          const std::size_t vertices = t.vertexCount(), triangles = t.triangleCount();
          requireRefused(t.removePoints(batch.data(), batch.size()), t, vertices, triangles,
                         "removePoints with a repeated id");
          batch.pop_back();
        }
        what = "removePoints of " + std::to_string(batch.size());
        require(model.removePoints(t, batch), what);
        break;
      }
      case 4: {  // remove a polyline
        if (lines.empty()) break;
        const std::size_t k = lines[arg % lines.size()];
        what = "removePolyline " + std::to_string(k);
        require(model.removePolyline(t, k), what);
        break;
      }
      case 5:
      case 6: {  // move a point (5) or a polyline's vertex (6)
        std::vector<std::uint32_t> from = ids;
        if ((b & 7) == 6 && !lines.empty())
          from = model.polylineVertexIds(lines[arg % lines.size()]);
        if (from.empty()) break;
        decoder.next(in, x, y);
        if (!valid(x, y)) break;
        const std::uint32_t id = from[(arg / 3) % from.size()];
        double tx = x, ty = y;
        if (arg % 3 == 2) {  // a nudge, an eighth of the way there: mostly within its star
          const std::vector<double> at = model.place(id);
          tx = at[0] + (x - at[0]) / 8;
          ty = at[1] + (y - at[1]) / 8;
          if (!valid(tx, ty)) break;
        }
        what = "movePoint " + std::to_string(id) + (verbose ? listed({tx, ty}, true) : "");
        const std::size_t vertices = t.vertexCount(), triangles = t.triangleCount();
        const Status s = model.movePoint(t, id, tx, ty);
        // Onto another point or polyline vertex: refused, nothing changed.
        if (s.code == StatusCode::InvalidArgument)
          requireRefused(s, t, vertices, triangles, what + " (onto a vertex)");
        else
          require(s, what);
        break;
      }
      default: {  // refine; or calls that must be refused
        const std::size_t vertices = t.vertexCount(), triangles = t.triangleCount();
        if (arg % 4 == 0) {
          RefineOptions r;
          r.minAngle = 20;
          r.maxSteinerPoints = 64;
          what = "refine";
          require(t.refine(r), what);
          break;
        }
        what = "bad ids";
        requireRefused(t.removePoint(0xFFFFFFF0u), t, vertices, triangles, "removePoint(big)");
        requireRefused(t.removePolyline(t.polylineCount()), t, vertices, triangles,
                       "removePolyline(count)");
        requireRefused(t.movePoint(0xFFFFFFF0u, 0, 0), t, vertices, triangles, "movePoint(big)");
        if (!ids.empty())
          requireRefused(t.movePoint(ids[0], NAN, 0), t, vertices, triangles, "movePoint(NaN)");
        break;
      }
    }
    if (verbose && !what.empty()) std::fprintf(stderr, "op %zu: %s\n", op, what.c_str());
    const std::string checked = model.check(t);
    if (!checked.empty()) fail("after " + what + ": " + checked);
  }
}

}  // namespace
}  // namespace geocdt::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace geocdt::fuzz;
  return fuzzOne(data, size, decode, print, run);
}
