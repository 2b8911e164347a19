#pragma once
// sculpt-cli bench deform: the per-frame cost of moving an embedded surface with a tet mesh.

#include "cli/cli_args.h"

namespace sculpt::cli {

/// Options of bench deform (besides --help).
extern const OptionSpec kBenchDeformOptions[4];

/// Runs the benchmark; prints the result line. Throws UsageError.
int benchDeform(const CliArgs& args);

}  // namespace sculpt::cli
