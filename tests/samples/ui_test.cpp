// The samples' panel typography and plot axes: text wraps between words but never inside a
// number or between a number and its unit; plot ranges never magnify round-off.
#include "plot.hpp"
#include "ui.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::samples {
namespace {

/// A monospace measure: 1 unit per character, so widths are character counts.
float characters(std::string_view s) { return static_cast<float>(s.size()); }

TEST(WrapLines, BreaksOnlyAtSpacesAndKeepsEachLineWithinTheWidth) {
  const std::string text = "the projectile moves 0.67 m per 1/60 s step; the boxes are 0.2 m";
  const std::vector<std::string> lines = wrapLines(text, 20.0f, characters);
  std::string rejoined;
  for (const std::string& line : lines) {
    EXPECT_LE(line.size(), 20u) << line;
    rejoined += (rejoined.empty() ? "" : " ") + line;
  }
  EXPECT_EQ(rejoined, text); // nothing lost, nothing split inside a word
}

TEST(WrapLines, NeverSeparatesANumberFromItsUnitOrAnEquationFromItsValue) {
  // Widths at which a plain word wrap would leave "s," or "m" alone on a line; each group
  // ("t = 0.0316 s,", 13 characters) fits a line.
  for (const float width : {13.0f, 14.0f, 17.0f, 20.0f, 24.0f}) {
    const std::vector<std::string> lines = wrapLines("terminal time t = 0.0316 s, x = 406.6 m", width, characters);
    for (const std::string& line : lines) {
      EXPECT_NE(line, "s,") << "width " << width;
      EXPECT_NE(line, "m") << "width " << width;
      EXPECT_EQ(line.find("0.0316") != std::string::npos, line.find("0.0316 s,") != std::string::npos)
          << "width " << width << ": " << line;
    }
  }
  const std::vector<std::string> wide = wrapLines("terminal time t = 0.0316 s, x = 406.6 m", 17.0f, characters);
  ASSERT_EQ(wide.size(), 3u);
  EXPECT_EQ(wide[0], "terminal time");
  EXPECT_EQ(wide[1], "t = 0.0316 s,");
  EXPECT_EQ(wide[2], "x = 406.6 m");
}

TEST(WrapLines, AGroupWiderThanTheLineBreaksAtItsSpacesAndNewlinesBreak) {
  const std::vector<std::string> lines = wrapLines("x = 1 m\nspeed 12 m/s", 4.0f, characters);
  // "x = 1 m" is wider than 4: its words fill lines as plain words do.
  const std::vector<std::string> expected{"x =", "1 m", "speed", "12", "m/s"};
  EXPECT_EQ(lines, expected);
}

TEST(PlotAxis, ASteadyValueWithRoundOffPlotsFlat) {
  // Total momentum 640 kg m/s with float noise of 1e-4: the axis spans at least 2% of 640.
  const PlotAxis axis = plotAxis(639.9999f, 640.0001f, readoutResolution("%.1f kg m/s"));
  EXPECT_GE(axis.upper - axis.lower, minimumSpanShare * 640.0f);
  EXPECT_LE(axis.lower, 639.9999f);
  EXPECT_GE(axis.upper, 640.0001f);
  // The noise is then under a ten-thousandth of the height: under a pixel.
  EXPECT_LT(0.0002f / (axis.upper - axis.lower), 1e-4f);
}

TEST(PlotAxis, AQuantityNearZeroSpansTenUnitsOfItsLastDigit) {
  const PlotAxis axis = plotAxis(-1e-6f, 2e-6f, readoutResolution("%.3f m"));
  EXPECT_GE(axis.upper - axis.lower, 0.01f);
}

TEST(PlotAxis, EndsOnRoundTicksAndKeepsTheDataSign) {
  const PlotAxis axis = plotAxis(3.0f, 47.0f, 0.0f, 5);
  EXPECT_FLOAT_EQ(axis.step, 10.0f);
  EXPECT_FLOAT_EQ(axis.lower, 0.0f);
  EXPECT_FLOAT_EQ(axis.upper, 50.0f);
  EXPECT_EQ(axis.decimals, 0);
  const PlotAxis positive = plotAxis(0.001f, 0.001f, 0.1f);
  EXPECT_GE(positive.lower, 0.0f); // a positive quantity's axis does not dip below zero
  const PlotAxis small = plotAxis(0.12f, 0.19f, 0.0f, 5);
  EXPECT_EQ(small.decimals, 2);
  EXPECT_NEAR(std::remainder(small.lower, small.step), 0.0f, 1e-6f);
}

TEST(ReadoutResolution, IsTenUnitsOfTheLastPrintedDigit) {
  EXPECT_FLOAT_EQ(readoutResolution("%.2f m/s"), 0.1f);
  EXPECT_FLOAT_EQ(readoutResolution("%.0f J"), 10.0f);
  EXPECT_FLOAT_EQ(readoutResolution("%.2f %%"), 0.1f);
  EXPECT_FLOAT_EQ(readoutResolution("x%.2f"), 0.1f);
  EXPECT_FLOAT_EQ(readoutResolution("%d"), 10.0f);
  EXPECT_FLOAT_EQ(readoutResolution("%.3g"), 0.0f);
}

} // namespace
} // namespace impetus::samples
