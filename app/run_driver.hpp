#pragma once
// The run and check commands: a scene loaded, its time loop, frames, checkpoints, summary.

#include "app/command_line.hpp"

namespace grainload::app {

/// Exit codes of the grainload CLI.
inline constexpr int kExitOk = 0;
inline constexpr int kExitSystemError = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitUnstable = 3;

/// `grainload run`: load, time loop, frames, checkpoints, summary.json. Returns an exit code;
/// bad input propagates as io::CaseError.
int run_case(const CommandLine& line);

/// `grainload check`: load and validate only; prints what the case contains.
int check_case(const CommandLine& line);

} // namespace grainload::app
