// The thrustsched command line as a function, so that the executable
// (app/main.cc) is one line and tests can run the very same path in a child
// process with observers injected (app/run_hooks.h).
//
//   app::RunHooks hooks;
//   hooks.on_progress = app::InterruptSelfAtFirstIncumbent;
//   int code = app::RunCli({"thrustsched", "solve", "scenario.json", "--out", "out/x"}, hooks);
//
// Exit codes: 0 solved (optimal or feasible) / check passed, 1 internal
// error, 2 bad input, 3 infeasible, 4 no solution within the time limit (or
// `simulate` interrupted), 5 the checked schedule fails (app/commands.h).
#ifndef THRUSTSCHED_APP_CLI_H_
#define THRUSTSCHED_APP_CLI_H_

#include <string>
#include <vector>

#include "app/run_hooks.h"

namespace thrustsched::app {

/// Parses argv (argv[0] is the program name) and runs the subcommand; prints
/// errors on stderr and returns the exit code (never throws).
int RunCli(int argc, char** argv, const RunHooks& hooks = {});
int RunCli(const std::vector<std::string>& args, const RunHooks& hooks = {});

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_CLI_H_
