#pragma once
// Quoting for commands the tests hand to std::system (paths may hold spaces or quotes).

#include <string>

#include "util/shell_command.h"

namespace sculpt::test {

using sculpt::shellQuote;

}  // namespace sculpt::test
