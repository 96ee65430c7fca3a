// Test helpers for bad-input checks: which field an impetus::Error names.
#pragma once

#include <impetus/error.hpp>

#include <gtest/gtest.h>

#include <string>

namespace impetus {

/// Runs `f` and returns the field() of the impetus::Error it throws, or "<nothing thrown>".
template <class F> std::string thrownField(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.field();
  }
  return "<nothing thrown>";
}

/// The message of the impetus::Error that `f` throws ("" when none).
template <class F> std::string thrownMessage(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

/// Expects `f` to throw an impetus::Error naming `field`.
template <class F> void expectErrorField(F&& f, const std::string& field) {
  try {
    f();
    ADD_FAILURE() << "no impetus::Error thrown; expected one naming " << field;
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

} // namespace impetus
