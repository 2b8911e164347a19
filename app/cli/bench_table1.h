#pragma once
// sculpt-cli bench table1: the paper's Table 1 (McDonnell & Qin 2007) beside this build, on the
// eight models of assets/table1/ (scripts/make-table1-models.py).

#include <string>
#include <vector>

namespace sculpt::cli {

extern const char* const kBenchTable1Usage;

/// `args` are those after "bench", starting with "table1". Returns the exit code.
int runBenchTable1(const std::vector<std::string>& args);

}  // namespace sculpt::cli
