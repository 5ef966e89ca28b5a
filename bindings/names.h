#pragma once
// The names JS knows the core's enums by, spelled as the JS API spells them. This is the one
// list of them: module.cpp registers each as an embind enum, web/ reads the names from the
// module, and tests/js/tables.test.js checks that web/index.d.ts and web/API.md say the same.
//
// Each is a switch without a default, and a missing case is an error in this file: an
// enumerator added to the core stops the build until it has its name here.
#include "geocdt/status.h"
#include "geocdt/triangulation.h"
#include "geocdt/voronoi.h"

#pragma clang diagnostic push
#pragma clang diagnostic error "-Wswitch"

namespace geocdt::wasm {

// nullptr past the last value: enums are numbered 0, 1, 2, ... and registered until then.
constexpr const char* jsName(StatusCode code) {
  switch (code) {
    case StatusCode::Ok: return "Ok";
    case StatusCode::InvalidArgument: return "InvalidArgument";
    case StatusCode::InvalidCoordinate: return "InvalidCoordinate";
    case StatusCode::OutOfMemory: return "OutOfMemory";
    case StatusCode::ConstraintUnresolved: return "ConstraintUnresolved";
    case StatusCode::InternalError: return "InternalError";
  }
  return nullptr;
}

constexpr const char* jsName(Location::Kind kind) {
  switch (kind) {
    case Location::Kind::Empty: return "empty";
    case Location::Kind::Outside: return "outside";
    case Location::Kind::Face: return "face";
    case Location::Kind::Edge: return "edge";
    case Location::Kind::Vertex: return "vertex";
    case Location::Kind::Invalid: return "invalid";
  }
  return nullptr;
}

constexpr const char* jsName(Keep keep) {
  switch (keep) {
    case Keep::All: return "all";
    case Keep::Inside: return "inside";
  }
  return nullptr;
}

constexpr const char* jsName(FillRule fill) {
  switch (fill) {
    case FillRule::EvenOdd: return "evenodd";
    case FillRule::NonZero: return "nonzero";
  }
  return nullptr;
}

constexpr const char* jsName(Phase phase) {
  switch (phase) {
    case Phase::Sort: return "sort";
    case Phase::Points: return "points";
    case Phase::Constraints: return "constraints";
    case Phase::Export: return "export";
  }
  return nullptr;
}

constexpr const char* jsName(Interpolation method) {
  switch (method) {
    case Interpolation::Linear: return "linear";
    case Interpolation::Natural: return "natural";
  }
  return nullptr;
}

constexpr const char* jsName(VoronoiClip clip) {
  switch (clip) {
    case VoronoiClip::Rings: return "rings";
    case VoronoiClip::Hull: return "hull";
    case VoronoiClip::Box: return "box";
  }
  return nullptr;
}

}  // namespace geocdt::wasm

#pragma clang diagnostic pop
