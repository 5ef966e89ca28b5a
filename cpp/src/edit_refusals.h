#pragma once
// The refusals of the editing calls (editing.cpp, point_batch_removal.cpp): an id or polyline
// that names nothing now, said in words that name it.
#include <cstdint>
#include <string>

#include "delaunay/delaunay.h"
#include "geocdt/status.h"
#include "triangulation_state.h"

namespace geocdt {

Status invalidEdit(const std::string& message, std::size_t index);
// What vertex v is, for messages ("a point", "a polyline's vertex", ...).
std::string describeVertex(const EditState& edit, std::uint32_t v);
// A vertex id that names a vertex now, or the reason it does not (call names the caller).
Status checkId(const Delaunay& d, std::uint32_t id, const char* call);

}  // namespace geocdt
