// Runs a command's body and turns exceptions into a message on stderr and an exit code.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace veduta {

int runGuarded(const std::function<void()> &body);

// Parses the command line into `app` and runs the chosen command, whose callback sets
// `exitCode`; help and version exit 0, a bad command line exits kExitBadUsage.
int runApp(CLI::App &app, int argc, char **argv, const int &exitCode);

}  // namespace veduta
