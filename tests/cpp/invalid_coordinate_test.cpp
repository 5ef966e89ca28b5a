// The digits of invalid coordinates in messages: as std::to_string prints them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "invalid_coordinate.h"

namespace geocdt {
namespace {

TEST(InvalidCoordinate, IntegersPrintAsToStringPrintsThem) {
  const double max = std::numeric_limits<double>::max();
  std::vector<double> values = {0.0,
                                -0.0,
                                1,
                                -1,
                                1e9,
                                999999999,
                                1e18,
                                0x1p53,
                                1e150,
                                1e200,
                                -3e150,
                                1.5e151,
                                max,
                                -max,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity()};
  for (int e = 0; e <= 1023; ++e) values.push_back(std::ldexp(1.0, e));
  std::mt19937_64 random(7);
  for (int k = 0; k < 20000; ++k) {
    const double v = std::ldexp(std::uniform_real_distribution<double>(0.5, 1)(random),
                                static_cast<int>(random() % 1025));
    values.push_back(v >= 0x1p53 ? v : std::round(v));
    values.push_back(-values.back());
  }
  for (const double v : values) EXPECT_EQ(integerToString(v), std::to_string(v)) << v;
}

TEST(InvalidCoordinate, MessagesNameTheAxisAndTheProblem) {
  EXPECT_EQ(describeInvalidCoordinate(std::nan(""), false),
            "x = NaN: coordinates must be finite numbers");
  EXPECT_EQ(describeInvalidCoordinate(-std::numeric_limits<double>::infinity(), true),
            "y = -inf: coordinates must be finite numbers");
  EXPECT_EQ(describeInvalidCoordinate(1e151, true),
            "y = " + std::to_string(1e151) + ": coordinates must lie within +-1e150");
}

}  // namespace
}  // namespace geocdt
