#include "polyline_file.h"

#include <cstdio>
#include <cstring>
#include <limits>

namespace geocdt::testing {
namespace {

// Byte-order independent encoding: the files are little-endian whatever the host is.
std::uint64_t loadLE(const unsigned char* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

void storeLE(std::uint64_t v, int bytes, std::vector<unsigned char>& out) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

double loadDouble(const unsigned char* p) {
  std::uint64_t bits = loadLE(p, 8);
  double d;
  std::memcpy(&d, &bits, 8);
  return d;
}

void storeDouble(double d, std::vector<unsigned char>& out) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, 8);
  storeLE(bits, 8, out);
}

std::string readAll(const std::string& path, std::vector<unsigned char>& bytes) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return path + ": cannot open";
  bytes.clear();
  unsigned char chunk[1 << 16];
  std::size_t got;
  while ((got = std::fread(chunk, 1, sizeof chunk, f)) > 0)
    bytes.insert(bytes.end(), chunk, chunk + got);
  bool failed = std::ferror(f) != 0;
  std::fclose(f);
  return failed ? path + ": read error" : std::string();
}

std::string writeAll(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return path + ": cannot create";
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = (std::fclose(f) == 0) && ok;
  return ok ? std::string() : path + ": write error";
}

bool hasMagic(const std::vector<unsigned char>& bytes, const char* magic) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), magic, 4) == 0;
}

}  // namespace

std::vector<PolylineView> PolylineSet::views() const {
  std::vector<PolylineView> out(polylineCount());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = view(i);
  return out;
}

std::size_t PolylineSet::segmentCount() const {
  std::size_t segments = 0;
  for (std::size_t i = 0; i < polylineCount(); ++i) {
    if (pointCount(i) > 1) segments += pointCount(i) - 1;
  }
  return segments;
}

void PolylineSet::add(const double* points, std::size_t count) {
  xy.insert(xy.end(), points, points + 2 * count);
  offsets.push_back(static_cast<std::uint32_t>(xy.size() / 2));
}

std::string readPolylineFile(const std::string& path, PolylineSet& out) {
  std::vector<unsigned char> bytes;
  std::string error = readAll(path, bytes);
  if (!error.empty()) return error;
  if (!hasMagic(bytes, "GPL1") || bytes.size() < 8) return path + ": not a GPL1 file";
  const std::uint64_t polylines = loadLE(bytes.data() + 4, 4);
  const std::uint64_t header = 8 + 4 * polylines;
  if (bytes.size() < header) return path + ": truncated polyline counts";
  out.offsets.assign(1, 0);
  out.offsets.reserve(polylines + 1);
  std::uint64_t points = 0;
  for (std::uint64_t i = 0; i < polylines; ++i) {
    points += loadLE(bytes.data() + 8 + 4 * i, 4);
    if (points > std::numeric_limits<std::uint32_t>::max()) return path + ": too many points";
    out.offsets.push_back(static_cast<std::uint32_t>(points));
  }
  if (bytes.size() != header + 16 * points) {
    return path + ": size does not match its " + std::to_string(points) + " points";
  }
  out.xy.resize(2 * points);
  const unsigned char* p = bytes.data() + header;
  for (std::size_t i = 0; i < out.xy.size(); ++i) out.xy[i] = loadDouble(p + 8 * i);
  return {};
}

std::string writePolylineFile(const std::string& path, const PolylineSet& set) {
  std::vector<unsigned char> bytes{'G', 'P', 'L', '1'};
  bytes.reserve(8 + 4 * set.polylineCount() + 8 * set.xy.size());
  storeLE(set.polylineCount(), 4, bytes);
  for (std::size_t i = 0; i < set.polylineCount(); ++i) storeLE(set.pointCount(i), 4, bytes);
  for (double d : set.xy) storeDouble(d, bytes);
  return writeAll(path, bytes);
}

std::string readPointFile(const std::string& path, std::vector<double>& xy) {
  std::vector<unsigned char> bytes;
  std::string error = readAll(path, bytes);
  if (!error.empty()) return error;
  if (!hasMagic(bytes, "GPT1") || bytes.size() < 12) return path + ": not a GPT1 file";
  const std::uint64_t n = loadLE(bytes.data() + 4, 8);
  if (n > (bytes.size() - 12) / 16 || bytes.size() != 12 + 16 * n) {
    return path + ": size does not match its " + std::to_string(n) + " points";
  }
  xy.resize(2 * n);
  for (std::size_t i = 0; i < xy.size(); ++i) xy[i] = loadDouble(bytes.data() + 12 + 8 * i);
  return {};
}

std::string writePointFile(const std::string& path, const std::vector<double>& xy) {
  std::vector<unsigned char> bytes{'G', 'P', 'T', '1'};
  bytes.reserve(12 + 8 * xy.size());
  storeLE(xy.size() / 2, 8, bytes);
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    storeDouble(xy[i], bytes);
    storeDouble(xy[i + 1], bytes);
  }
  return writeAll(path, bytes);
}

std::string readPolygonFile(const std::string& path, std::vector<std::int32_t>& polylinePolygons) {
  std::vector<unsigned char> bytes;
  std::string error = readAll(path, bytes);
  if (!error.empty()) return error;
  if (!hasMagic(bytes, "GPG1") || bytes.size() < 8) return path + ": not a GPG1 file";
  const std::uint64_t polygons = loadLE(bytes.data() + 4, 4);
  if (bytes.size() != 8 + 4 * polygons) return path + ": size does not match its polygons";
  polylinePolygons.clear();
  for (std::uint64_t g = 0; g < polygons; ++g)
    polylinePolygons.insert(polylinePolygons.end(), loadLE(bytes.data() + 8 + 4 * g, 4),
                            static_cast<std::int32_t>(g));
  return {};
}

}  // namespace geocdt::testing
