#pragma once
// Test helper of the wings tests: the InputError a call throws (a test failure if none).

#include <gtest/gtest.h>

#include "wings/loader/input_error.hpp"

template <typename F>
flapsim::InputError expect_input_error(F f) {
  try {
    f();
  } catch (const flapsim::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return flapsim::InputError("", 0, "", "");
}
