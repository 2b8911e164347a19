#include "cli/commands.h"

namespace sculpt::cli {

const char* const kDevicesUsage = "  devices (not yet built)";
int runDevicesCommand(const std::vector<std::string>&) { return 2; }

}  // namespace sculpt::cli
