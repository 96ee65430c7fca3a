// Table-driven checks of the input validation audit (docs/reliability.md, "Input validation"):
// each row calls the library with one bad value and expects an impetus::Error that names the
// field and shows the value, in the library's own format "<field> = <value>: <requirement>".
#pragma once

#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace impetus::testing {

inline constexpr float nanf = std::numeric_limits<float>::quiet_NaN();
inline constexpr float inff = std::numeric_limits<float>::infinity();
inline constexpr double nand = std::numeric_limits<double>::quiet_NaN();
inline constexpr double infd = std::numeric_limits<double>::infinity();

/// One bad input: the field impetus::Error::field() must name, the value as the message shows
/// it ("nan", "inf", "-1", ...), and the call that must be refused.
struct Rejection {
  std::string field;
  std::string value;
  std::function<void()> call;
};

/// Runs every row and expects each to throw impetus::Error naming its field, with the message
/// "<field> = <value>: ..." (so a user sees both what and which value was wrong).
inline void expectRejected(const std::vector<Rejection>& rows) {
  for (const Rejection& row : rows) {
    const std::string shown = row.field + " = " + row.value;
    SCOPED_TRACE(shown);
    try {
      row.call();
      ADD_FAILURE() << "accepted " << shown;
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), row.field) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(shown + ":", 0), 0U) << "message: " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << shown << " raised a non-impetus exception: " << e.what();
    }
  }
}

/// Runs every call and expects none to throw: the boundary values that are valid.
inline void expectAccepted(const std::vector<std::pair<std::string, std::function<void()>>>& rows) {
  for (const auto& [what, call] : rows) {
    SCOPED_TRACE(what);
    try {
      call();
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << " was refused: " << e.what();
    }
  }
}

} // namespace impetus::testing
