// sculpt-cli: the batch face of the program. Dispatches to one subcommand per file; every failure
// ends as one "error: ..." line on stderr and exit code 2, never as a crash.

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "allocator/huge_page_heap.h"
#include "cli/bench_table1.h"
#include "cli/cli_common.h"
#include "cli/commands.h"

namespace {

void printUsage(std::ostream& out) {
  out << "usage: sculpt-cli <command> [options]\n\n"
         "commands:\n"
      << sculpt::cli::kInfoUsage << '\n'
      << sculpt::cli::kSubdivideUsage << '\n'
      << sculpt::cli::kStaticUsage << '\n'
      << sculpt::cli::kSimulateUsage << '\n'
      << sculpt::cli::kDeformUsage << '\n'
      << sculpt::cli::kBenchUsage << sculpt::cli::kBenchTable1Usage << '\n'
      << sculpt::cli::kStudyUsage << '\n'
      << sculpt::cli::kDevicesUsage << '\n'
      << sculpt::cli::kHapticsUsage << '\n'
      << sculpt::cli::kRecordUsage << '\n'
      << "Run 'sculpt-cli <command> --help' for one command. Exit code 0 on success, 1 when a\n"
         "solve did not converge or a step failed (static, simulate, bench), 2 on bad input or\n"
         "usage (with one line on stderr naming the file and the problem).\n";
}

int dispatch(const std::vector<std::string>& args) {
  using namespace sculpt::cli;
  if (args.empty()) {
    printUsage(std::cerr);
    return kExitBadInput;
  }
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "--help" || command == "-h" || command == "help") {
    printUsage(std::cout);
    return kExitSuccess;
  }
  if (command == "info") return runInfoCommand(rest);
  if (command == "subdivide") return runSubdivideCommand(rest);
  if (command == "bench") return runBenchCommand(rest);
  if (command == "static") return runStaticCommand(rest);
  if (command == "simulate") return runSimulateCommand(rest);
  if (command == "deform") return runDeformCommand(rest);
  if (command == "study") return runStudyCommand(rest);
  if (command == "devices") return runDevicesCommand(rest);
  if (command == "haptics") return runHapticsCommand(rest);
  if (command == "record") return runRecordCommand(rest);
  return printError("unknown command '" + command + "' (run 'sculpt-cli --help')");
}

}  // namespace

int main(int argc, char** argv) {
  sculpt::app::useHugePageHeap(argv);
  // The subcommands report their own errors; this is the last line of defence.
  try {
    return dispatch(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::bad_alloc&) {
    return sculpt::cli::printError("out of memory");
  } catch (const std::exception& error) {
    return sculpt::cli::printError(error.what());
  } catch (...) {
    return sculpt::cli::printError("unexpected failure");
  }
}
