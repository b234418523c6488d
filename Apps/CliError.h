// The command line's one error type: a line for stderr and the exit code.
// Usage errors (exit code 2) add a hint to the help of their command.
#ifndef flowrecon_cli_CliError_h
#define flowrecon_cli_CliError_h

#include <stdexcept>
#include <string>

namespace flowrecon::cli
{

constexpr int ExitFailure = 1; ///< bad input or a failed computation
constexpr int ExitUsage = 2;
constexpr int ExitInterrupted = 130; ///< Ctrl-C

class Error : public std::runtime_error
{
public:
  Error(int exitCode, const std::string& message, std::string help = std::string())
    : std::runtime_error(message)
    , ExitCode(exitCode)
    , Help(std::move(help))
  {
  }
  int ExitCode;
  std::string Help; ///< "flowrecon CMD --help" for a usage error, else ""
};

/// A command-line mistake in `command` ("" for none): exit code 2 and a hint to
/// 'flowrecon [command] --help'.
inline Error Usage(const std::string& message, const std::string& command = std::string())
{
  return Error(ExitUsage, message, "flowrecon " + (command.empty() ? "" : command + " ") + "--help");
}

/// Bad input or a failed computation: one line, exit code 1.
inline Error Failure(const std::string& message)
{
  return Error(ExitFailure, message);
}

/// Ctrl-C was pressed.
inline Error Interrupted()
{
  return Error(ExitInterrupted, "aborted");
}

} // namespace flowrecon::cli

#endif
