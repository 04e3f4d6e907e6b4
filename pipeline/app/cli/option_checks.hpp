#pragma once
/// \file option_checks.hpp
/// \brief Checks of option values with short messages. CLI11's PositiveNumber and
/// NonNegativeNumber say "Value 0 not in range 0.000000 to 1797693134862315708145…" (the
/// whole of DBL_MAX written out) for `--threads 0` or `--spring-scale -1`.

#include <CLI/CLI.hpp>

namespace flapsim::cli {

/// A whole number in [lo, hi] ("--threads: 0 is not a whole number from 1 to 4096").
CLI::Validator whole_number(long lo, long hi);

/// A finite number > 0.
CLI::Validator positive_number();

/// A path option that must not be empty (-o, --chain): an empty value — often an unset shell
/// variable, `--chain "$CHAIN"` — is a usage error instead of silently meaning "no chain"
/// (the wing reduced in process) or "the default folder".
CLI::Validator non_empty_option();

}  // namespace flapsim::cli
