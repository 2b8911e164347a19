#pragma once
// The sculpt-cli subcommands. Each takes the arguments after its name and returns the exit code.

#include <string>
#include <vector>

namespace sculpt::cli {

int runInfoCommand(const std::vector<std::string>& args);
int runSubdivideCommand(const std::vector<std::string>& args);
int runBenchCommand(const std::vector<std::string>& args);
int runStaticCommand(const std::vector<std::string>& args);
int runSimulateCommand(const std::vector<std::string>& args);
int runDeformCommand(const std::vector<std::string>& args);
int runStudyCommand(const std::vector<std::string>& args);
int runDevicesCommand(const std::vector<std::string>& args);
int runHapticsCommand(const std::vector<std::string>& args);
int runRecordCommand(const std::vector<std::string>& args);

/// One-paragraph usage of each subcommand (shown by `--help` and in the main usage).
extern const char* const kInfoUsage;
extern const char* const kSubdivideUsage;
extern const char* const kBenchUsage;
extern const char* const kStaticUsage;
extern const char* const kSimulateUsage;
extern const char* const kDeformUsage;
extern const char* const kStudyUsage;
extern const char* const kDevicesUsage;
extern const char* const kHapticsUsage;
extern const char* const kRecordUsage;

}  // namespace sculpt::cli
