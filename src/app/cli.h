#pragma once
/// \file cli.h
/// impetus-cli: the headless runner (`run` and `validate`), as the public contract section 2 says.

#include <iosfwd>
#include <span>
#include <string>

namespace impetus::app {

/// Process exit codes of impetus-cli.
enum ExitCode : int {
    kExitOk = 0, ///< success
    kExitRuntimeFailure = 1, ///< failure at run time: a non-finite state, an output file not written
    kExitBadInput = 2, ///< bad usage or a bad scene; the message is on stderr
};

/// Runs impetus-cli with `args` (without the program name), writing normal output to `out` and
/// messages to `err`. `errIsTerminal` turns on the progress line for long runs. Returns the exit
/// code. Never throws.
int runCli(std::span<const std::string> args, std::ostream& out, std::ostream& err, bool errIsTerminal);

} // namespace impetus::app
