#pragma once
// Errors are values in the core: a code, a message a user can act on, and the offending
// input index where there is one. The bindings turn them into JS exceptions.
#include <cstddef>
#include <string>

namespace geocdt {

enum class StatusCode {
  Ok = 0,
  InvalidArgument,    // wrong shape of input (odd length, null pointer with a count)
  InvalidCoordinate,  // NaN, infinity, or |coordinate| > kMaxCoordinate
  OutOfMemory,        // an allocation failed; the triangulation is unchanged or cleared
  // No longer returned: crossings that cannot be computed are snap-rounded. The value stays
  // so that the codes after it keep their numbers (the bindings map codes by number).
  ConstraintUnresolved,
  InternalError,  // a broken invariant (say, point location or a segment walk that finds no
                  // way on): a bug, reported rather than hung on
};

inline constexpr std::size_t kNoIndex = static_cast<std::size_t>(-1);

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;
  std::size_t index = kNoIndex;    // offending point / polyline index, if any
  std::size_t segment = kNoIndex;  // offending segment within that polyline, if any

  bool ok() const { return code == StatusCode::Ok; }
  static Status success() { return {}; }
};

// Largest accepted |coordinate|. The predicates are exact for every finite double (predicates.h:
// big integers take the widest exponent spans); the limit keeps what is computed in floating
// point from coordinate differences (areas, circumcentres, crossing estimates) finite.
inline constexpr double kMaxCoordinate = 1e150;

}  // namespace geocdt
