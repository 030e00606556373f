#include "pipeline/config/number_format.hpp"

#include <gtest/gtest.h>

#include <string>

namespace silva::pipeline {
namespace {

TEST(NumberFormat, WholeNumbersHaveNoExponent) {
  EXPECT_EQ(format_number(150), "150");
  EXPECT_EQ(format_number(1000000), "1000000");
  EXPECT_EQ(format_number(9999999999.0), "9999999999");
  EXPECT_EQ(format_number(-45), "-45");
}

TEST(NumberFormat, FractionsAreShortest) {
  EXPECT_EQ(format_number(0.05), "0.05");
  EXPECT_EQ(format_number(0.015), "0.015");
}

TEST(NumberFormat, TomlFloatsAlwaysReadAsFloats) {
  EXPECT_EQ(format_toml_float(90), "90.0");
  EXPECT_EQ(format_toml_float(0.01), "0.01");
  EXPECT_EQ(format_toml_float(1e-7), "1e-07");
}

TEST(NumberFormat, RoundTripsEveryDouble) {
  for (double v : {0.1, 1.0 / 3.0, 2.5e-9, 123456.789, 1e300}) {
    EXPECT_EQ(std::stod(format_toml_float(v)), v) << v;
  }
}

}  // namespace
}  // namespace silva::pipeline
