// catchOutOfMemory: the one place where memory exhaustion, the core's only exception, becomes a
// Status (out_of_memory.h). The wasm tests run it for real (tests/js/memory.test.js).
#include "out_of_memory.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <vector>

namespace geocdt {
namespace {

TEST(OutOfMemory, WorkThatSucceedsKeepsItsStatusAndNeedsNoUndo) {
  int undone = 0;
  const Status ok = catchOutOfMemory([] { return Status::success(); }, [&] { ++undone; });
  EXPECT_TRUE(ok.ok());
  const Status bad = catchOutOfMemory(
      [] {
        return Status{StatusCode::InvalidArgument, "bad input"};
      },
      [&] { ++undone; });
  EXPECT_EQ(bad.code, StatusCode::InvalidArgument);
  EXPECT_EQ(bad.message, "bad input");
  EXPECT_EQ(undone, 0);
}

TEST(OutOfMemory, BadAllocIsUndoneAndReported) {
  std::vector<int> state{1, 2, 3};
  const Status s = catchOutOfMemory(
      [&]() -> Status {
        state.push_back(4);
        throw std::bad_alloc();
      },
      [&] { state.clear(); });
  EXPECT_EQ(s.code, StatusCode::OutOfMemory);
  EXPECT_EQ(s.message, kOutOfMemoryMessage);
  EXPECT_TRUE(state.empty());
}

TEST(OutOfMemory, LengthErrorCountsAsOutOfMemoryWithTheCallersMessage) {
  int undone = 0;
  const Status s = catchOutOfMemory(
      [] {
        std::vector<double> v;
        v.resize(v.max_size() + std::size_t{1});  // more than a vector can hold
        return Status::success();
      },
      [&] { ++undone; }, "out of memory: no room");
  EXPECT_EQ(s.code, StatusCode::OutOfMemory);
  EXPECT_EQ(s.message, "out of memory: no room");
  EXPECT_EQ(undone, 1);
}

}  // namespace
}  // namespace geocdt
