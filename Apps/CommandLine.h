// The command line through CLI11: commands with the help layout of
// 'flowrecon [COMMAND] --help' (a usage line, a paragraph, the options, the
// input formats), number options with their own messages, and parse errors
// as usage errors worded as the tests and scripts know them.
#ifndef flowrecon_cli_CommandLine_h
#define flowrecon_cli_CommandLine_h

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace flowrecon::cli
{

/// The top-level app: `description` under its usage line, --help and --version
/// (which prints `version`).
void SetUpApp(CLI::App& app, const std::string& description, const std::string& version);

/// Adds the command `name`: `summary` is its line in 'flowrecon --help',
/// 'flowrecon NAME --help' shows "Usage: flowrecon NAME `synopsis`", then
/// `description`; its argument INPUT goes to `input`.
CLI::App* AddCommand(CLI::App& app, const char* name, const char* summary, const char* synopsis,
  const char* description, std::string& input);

/// A number option, kept as text until Number reads it, so that its error
/// comes with the command's other checks.
struct NumberArg
{
  const char* Name; ///< the long name, for messages
  std::string Text;
  bool Given = false;
};

/// Adds `arg` to `command` as `names` ("--tr" or "-j,--threads").
CLI::Option* AddNumber(CLI::App* command, const char* names, NumberArg& arg,
  const char* placeholder, const char* help);

/// Whether `arg` asks for a value chosen from the data: not given, or "auto".
bool IsAutomatic(const NumberArg& arg);

/// The value of `arg` ("inf" for infinity), `fallback` when not given; a usage
/// error of `command` when it is not a number.
double Number(const NumberArg& arg, double fallback, const std::string& command);

/// Parses the command line into `app`'s options. Returns the command given,
/// or nullptr when the help or the version was printed. Throws usage errors.
CLI::App* ParseCommandLine(CLI::App& app, int argc, char** argv);

/// The output file `output` of `command`, with one of `extensions`; its
/// directory must exist.
std::string OutputPath(
  const std::string& output, const std::string& command, const std::vector<std::string>& extensions);

} // namespace flowrecon::cli

#endif
