#pragma once
/// \file numerical_stage.hpp
/// \brief Runs a computation (FEM solve, reduction, run setup) and reports a failure of
/// the numerics inside it (a solver that does not converge, a degenerate system) as
/// flapsim::NumericalFailure, exit status 3. Errors that already say what they are pass
/// through unchanged: bad input (InputError, 2), output errors (io::OutputError, 4),
/// out of memory (std::bad_alloc, 4), interruption (Interrupted, 130/143).

#include <new>
#include <string>
#include <string_view>

#include "pipeline/app/interruption.hpp"
#include "pipeline/fsi/numerical_failure.hpp"
#include "pipeline/io/atomic_file.hpp"
#include "wings/loader/input_error.hpp"

namespace flapsim::app {

template <typename F>
decltype(auto) numerical_stage(std::string_view stage, F&& compute) {
  try {
    return compute();
  } catch (const InputError&) {
    throw;
  } catch (const NumericalFailure&) {
    throw;
  } catch (const io::OutputError&) {
    throw;
  } catch (const Interrupted&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw NumericalFailure(std::string(stage) + ": " + e.what());
  }
}

}  // namespace flapsim::app
