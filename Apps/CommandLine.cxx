#include "CommandLine.h"

#include "CliError.h"
#include "OutputFiles.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace flowrecon::cli
{

namespace
{

const char* const InputHelp =
  "INPUT: .xyz .txt .pts .pwn (x y z per line, extra columns ignored), .csv,\n"
  "       .off, .ply, .obj, .stl, .las, legacy .vtk, VTK XML (.vtp .vtu .vts .vtr\n"
  "       .vti .vtm ...): the points are used.";

const char* const ExitHelp =
  "Exit status: 0 success, 1 bad input or failed computation, 2 usage error,\n"
  "130 interrupted.";

// 'flowrecon --help' and 'flowrecon CMD --help': the usage line first, then
// the description, the options ("-o, --output OUT.vtm"), the commands with
// their summaries, and the footer.
// `text` with its spaces turned into line breaks where a line would pass
// `width`; a word longer than `width` stands on a line of its own.
std::string Wrap(const std::string& text, std::size_t width)
{
  std::istringstream words(text);
  std::string wrapped, word;
  std::size_t line = 0;
  while (words >> word)
  {
    if (line > 0 && line + 1 + word.size() > width)
    {
      wrapped += '\n';
      line = 0;
    }
    else if (line > 0)
    {
      wrapped += ' ';
      ++line;
    }
    wrapped += word;
    line += word.size();
  }
  return wrapped;
}

class HelpFormatter : public CLI::Formatter
{
public:
  HelpFormatter() { this->column_width(26); }

  std::string make_description(const CLI::App*) const override { return std::string(); }

  // INPUT is in the usage line and the footer.
  std::string make_positionals(const CLI::App*) const override { return std::string(); }

  std::string make_usage(const CLI::App* app, std::string) const override
  {
    const bool top = app->get_parent() == nullptr;
    return "Usage: flowrecon " +
      (top ? std::string("COMMAND [options] INPUT")
           : app->get_name() + " " + this->Commands.at(app->get_name()).second) +
      "\n\n" + app->get_description() + "\n";
  }

  std::string make_subcommand(const CLI::App* command) const override
  {
    std::ostringstream out;
    CLI::detail::format_help(out, command->get_name(), this->Commands.at(command->get_name()).first, 15);
    return out.str();
  }

  // Option help is written as plain sentences and wrapped here, so that every
  // line of 'flowrecon CMD --help' fits in 80 columns.
  std::string make_option_desc(const CLI::Option* option) const override
  {
    return Wrap(option->get_description(), 80 - this->get_column_width());
  }

  std::string make_option_name(const CLI::Option* option, bool positional) const override
  {
    if (positional)
    {
      return option->get_name(true, false);
    }
    std::string names;
    for (const std::string& s : option->get_snames())
    {
      names += (names.empty() ? "-" : ", -") + s;
    }
    for (const std::string& l : option->get_lnames())
    {
      names += (names.empty() ? "    --" : ", --") + l;
    }
    return names;
  }

  std::map<std::string, std::pair<std::string, std::string>> Commands; // summary, synopsis
};

bool IsOption(const std::string& word)
{
  return word.size() >= 2 && word[0] == '-';
}

CLI::App* Chosen(const CLI::App& app)
{
  const std::vector<CLI::App*> commands = app.get_subcommands();
  return commands.empty() ? nullptr : commands.front();
}

// The words CLI11 did not place: at the top, an unknown command or option; in a
// command, an unknown option first, then an argument too many.
void RejectExtras(const CLI::App& app, const CLI::App* command)
{
  const std::vector<std::string> top = app.remaining();
  if (!top.empty())
  {
    throw Usage(
      (IsOption(top.front()) ? "unknown option '" : "unknown command '") + top.front() + "'");
  }
  if (!command)
  {
    return;
  }
  std::string option, extra;
  bool ended = false; // after "--", every word is an argument
  for (const std::string& word : command->remaining())
  {
    if (!ended && word == "--")
    {
      ended = true;
    }
    else if (!ended && IsOption(word))
    {
      if (option.empty())
      {
        option = word.substr(0, word.rfind("--", 0) == 0 ? word.find('=') : std::string::npos);
      }
    }
    else if (extra.empty())
    {
      extra = word;
    }
  }
  const std::string& name = command->get_name();
  if (!option.empty())
  {
    throw Usage("unknown option '" + option + "' for '" + name + "'", name);
  }
  if (!extra.empty())
  {
    throw Usage("unexpected argument '" + extra + "'", name);
  }
}

} // namespace

void SetUpApp(CLI::App& app, const std::string& description, const std::string& version)
{
  app.description(description);
  app.formatter(std::make_shared<HelpFormatter>());
  // As before CLI11: an option given twice keeps its last value. (Commands
  // inherit these defaults.)
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.set_help_flag("-h,--help", "show this help; 'flowrecon COMMAND --help' for a command");
  app.add_flag_callback(
    "--version",
    [version]() {
      std::cout << version << "\n";
      throw CLI::Success();
    },
    "print the version");
  app.footer(std::string(InputHelp) + "\n\n" + ExitHelp);
  app.require_subcommand(0, 1);
  app.allow_extras(); // RejectExtras words the errors
}

CLI::App* AddCommand(CLI::App& app, const char* name, const char* summary, const char* synopsis,
  const char* description, std::string& input)
{
  auto formatter = std::dynamic_pointer_cast<HelpFormatter>(app.get_formatter());
  formatter->Commands[name] = { summary, synopsis };
  CLI::App* command = app.add_subcommand(name, description);
  command->group("Commands");
  command->set_help_flag("-h,--help", "show this help");
  command->footer(InputHelp);
  command->allow_extras();
  command->add_option("INPUT", input);
  return command;
}

CLI::Option* AddNumber(
  CLI::App* command, const char* names, NumberArg& arg, const char* placeholder, const char* help)
{
  return command
    ->add_option_function<std::string>(
      names,
      [&arg](const std::string& text) {
        arg.Text = text;
        arg.Given = true;
      },
      help)
    ->type_name(placeholder);
}

bool IsAutomatic(const NumberArg& arg)
{
  return !arg.Given || arg.Text == "auto";
}

double Number(const NumberArg& arg, double fallback, const std::string& command)
{
  if (!arg.Given)
  {
    return fallback;
  }
  double value = 0; // CLI11's conversion (strtold): also 'inf' and 'infinity'
  if (!CLI::detail::lexical_cast(arg.Text, value) || std::isnan(value))
  {
    throw Usage(std::string("option '") + arg.Name + "' needs a number, not '" + arg.Text + "'",
      command);
  }
  return value;
}

CLI::App* ParseCommandLine(CLI::App& app, int argc, char** argv)
{
  if (argc < 2)
  {
    throw Usage("missing command");
  }
  if (std::string(argv[1]) == "help")
  {
    std::cout << app.help();
    return nullptr;
  }
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << app.help(); // the command's, if one was given
    return nullptr;
  }
  catch (const CLI::Success&) // --version
  {
    return nullptr;
  }
  catch (const CLI::ArgumentMismatch&)
  {
    // An option without its value: only the last word can be one.
    const CLI::App* command = Chosen(app);
    RejectExtras(app, command);
    const std::string name = argv[argc - 1];
    const CLI::Option* option = command ? command->get_option_no_throw(name) : nullptr;
    throw Usage("option '" + name + "' needs a value" +
        (option ? " (" + option->get_type_name() + ")" : std::string()),
      command ? command->get_name() : std::string());
  }
  catch (const CLI::ParseError& e)
  {
    const CLI::App* command = Chosen(app);
    RejectExtras(app, command);
    throw Usage(e.what(), command ? command->get_name() : std::string());
  }
  CLI::App* command = Chosen(app);
  RejectExtras(app, command);
  if (!command)
  {
    throw Usage("missing command");
  }
  if (command->get_option("INPUT")->empty())
  {
    throw Usage("'" + command->get_name() + "' needs an INPUT file", command->get_name());
  }
  return command;
}

std::string OutputPath(
  const std::string& output, const std::string& command, const std::vector<std::string>& extensions)
{
  if (output.empty())
  {
    throw Usage("'" + command + "' needs an output file: -o OUT" + extensions.front(), command);
  }
  if (std::find(extensions.begin(), extensions.end(), ExtensionOf(output)) == extensions.end())
  {
    std::string list;
    for (const std::string& e : extensions)
    {
      list += (list.empty() ? "" : " or ") + e;
    }
    throw Usage("the output file must have the " + list + " extension: '" + output + "'", command);
  }
  RequireDirectory(output);
  return output;
}

} // namespace flowrecon::cli
