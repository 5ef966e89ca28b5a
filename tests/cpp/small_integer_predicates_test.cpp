// The small-integer predicates (exact/small_integer_predicates.h) give the signs of the
// filtered exact ones on every integer input they are made for: spans up to 2^14, at offsets
// up to 2^40, on lattices where collinear and cocircular points are the rule, and at the
// extremes of the span where the in-circle products near 2^60.
#include <gtest/gtest.h>

#include <random>

#include "exact/small_integer_predicates.h"
#include "geocdt/predicates.h"

namespace geocdt {
namespace {

TEST(SmallIntegerPredicates, AgreeWithTheExactPredicates) {
  std::mt19937_64 rng(3);
  for (const double span : {4.0, 64.0, 4096.0, kSmallIntegerSpan}) {
    for (const double offset : {0.0, -8192.0, 1048576.0, 0x1p40}) {
      std::uniform_int_distribution<int> coordinate(0, static_cast<int>(span));
      for (int i = 0; i < 20000; ++i) {
        double v[8];
        for (double& c : v) c = offset + coordinate(rng);
        if (i % 4 == 0) {  // corners of the span: the largest products
          for (double& c : v) c = offset + (rng() % 2 ? span : 0);
        }
        ASSERT_EQ(orient2dSmallIntegers(v[0], v[1], v[2], v[3], v[4], v[5]),
                  orient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
        ASSERT_EQ(incircleSmallIntegers(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
                  incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]))
            << span << " " << offset;
      }
    }
  }
}

TEST(SmallIntegerPredicates, EligibleInputs) {
  const double tile[] = {0, 0, 4096, 0, 4096, 4096, -128, 4224};
  EXPECT_TRUE(areSmallIntegers(tile, 4));
  const double wide[] = {0, 0, kSmallIntegerSpan + 1, 0};
  EXPECT_FALSE(areSmallIntegers(wide, 2));
  const double lonLat[] = {0, 0, 12.5, 3};
  EXPECT_FALSE(areSmallIntegers(lonLat, 2));
  const double huge[] = {0x1p60, 0, 0x1p60 + 4096, 0};
  EXPECT_FALSE(areSmallIntegers(huge, 2));  // integers, but beyond the exact conversion
  EXPECT_TRUE(areSmallIntegers(tile, 0));
}

}  // namespace
}  // namespace geocdt
