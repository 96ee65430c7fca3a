// impetus::Error and the require* checks: the message format "field = value: requirement", the
// value formatting (shortest round trip, nan, inf) and the std::runtime_error base.
#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace impetus {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

template <class F> Error caught(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  return Error("<nothing thrown>", "<nothing thrown>");
}

TEST(Error, message_names_field_value_and_requirement) {
  const Error e = caught([] { static_cast<void>(requirePositive(-2.0, "mass")); });
  EXPECT_STREQ(e.what(), "mass = -2: must be finite and positive");
  EXPECT_EQ(e.field(), "mass");
}

TEST(Error, non_finite_values_format_as_nan_and_inf) {
  EXPECT_STREQ(caught([] { static_cast<void>(requireFinite(std::nan(""), "speed")); }).what(),
               "speed = nan: must be finite");
  EXPECT_STREQ(caught([] { static_cast<void>(requirePositive(inf, "radius")); }).what(),
               "radius = inf: must be finite and positive");
  EXPECT_STREQ(caught([] { static_cast<void>(requireNonNegative(-inf, "length")); }).what(),
               "length = -inf: must be finite and non-negative");
  EXPECT_EQ(formatValue(std::nan("")), "nan");
  EXPECT_EQ(formatValue(-std::nan("")), "nan");
  EXPECT_EQ(formatValue(inf), "inf");
  EXPECT_EQ(formatValue(-inf), "-inf");
}

TEST(Error, values_format_as_shortest_round_trip) {
  EXPECT_EQ(formatValue(0.1), "0.1");
  EXPECT_EQ(formatValue(-2.0), "-2");
  EXPECT_EQ(formatValue(1e-300), "1e-300");
  EXPECT_EQ(formatValue(0.0), "0");
  // Round trip: parsing the text gives back the same double.
  for (double v : {1.0 / 3.0, 6.674'30e-11, 299'792'458.0, -123.456e78}) {
    EXPECT_EQ(std::stod(formatValue(v)), v) << formatValue(v);
  }
}

TEST(Error, checks_return_accepted_values_and_reject_at_the_boundary) {
  EXPECT_EQ(requireFinite(-3.5, "x"), -3.5);
  EXPECT_EQ(requirePositive(1e-300, "x"), 1e-300);
  EXPECT_EQ(requireNonNegative(0.0, "x"), 0.0);
  EXPECT_THROW(static_cast<void>(requirePositive(0.0, "x")), Error);
  EXPECT_THROW(static_cast<void>(requireNonNegative(-1e-300, "x")), Error);
  EXPECT_THROW(static_cast<void>(requireFinite(inf, "x")), Error);
  EXPECT_STREQ(caught([] { static_cast<void>(requireNonNegative(-0.5, "density")); }).what(),
               "density = -0.5: must be finite and non-negative");
}

TEST(Error, throw_invalid_builds_the_message) {
  const Error e = caught([] { throwInvalid("parts[2].mass", 1.5, "is odd"); });
  EXPECT_STREQ(e.what(), "parts[2].mass = 1.5: is odd");
  EXPECT_EQ(e.field(), "parts[2].mass");
}

TEST(Error, derives_from_runtime_error) {
  static_assert(std::is_base_of_v<std::runtime_error, Error>);
  try {
    static_cast<void>(requirePositive(-1.0, "mass"));
    ADD_FAILURE() << "nothing thrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "mass = -1: must be finite and positive");
  }
}

} // namespace
} // namespace impetus
