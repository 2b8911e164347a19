#include "cli/commands.h"

namespace sculpt::cli {

const char* const kHapticsUsage = "  haptics (not yet built)";
int runHapticsCommand(const std::vector<std::string>&) { return 2; }

}  // namespace sculpt::cli
