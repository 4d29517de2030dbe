// dfvn-sample: the command line. It parses arguments, validates them and calls the library; each
// subcommand's options and glue live in apps/<subcommand>_command.cpp, the shared ones in apps/options.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "options.hpp"
#include "dfvn/sampling/method.hpp"

namespace {

using dfvn_cli::fail;
using dfvn_cli::kProgram;

const std::vector<std::string> kSubcommands = {"sample", "field", "reproduce", "stats", "animate"};

// CLI11 echoes arguments verbatim in its messages: shorten and escape each one that is long or holds
// bytes that are not printable ASCII (core/message_text.hpp).
std::string with_safe_echoes(std::string message, std::vector<std::string> args) {
  std::sort(args.begin(), args.end(), [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const std::string& arg : args) {
    const bool printable = std::all_of(arg.begin(), arg.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
    if (arg.empty() || (printable && arg.size() <= dfvn::kMaxEchoChars)) continue;
    const std::string safe = dfvn::quote_for_message(arg);
    for (std::size_t at = message.find(arg); at != std::string::npos; at = message.find(arg, at + safe.size()))
      message.replace(at, arg.size(), safe);
  }
  return message;
}

// The deepest subcommand on the command line, e.g. 'reproduce' in "reproduce table3".
CLI::App* deepest_subcommand(CLI::App& app) {
  CLI::App* deepest = &app;
  while (!deepest->get_subcommands().empty()) deepest = deepest->get_subcommands().front();
  return deepest;
}

// A parse error as the tool's own line: unexpected arguments in the order given, and a missing
// subcommand with the names it could have been.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& error) {
  CLI::App* deepest = deepest_subcommand(app);
  const std::vector<std::string> unexpected = app.remaining(true);
  if (deepest->get_require_subcommand_min() > 0 && deepest->get_subcommands().empty()) {
    std::string names;
    for (const CLI::App* sub : deepest->get_subcommands([](CLI::App*) { return true; }))
      names += (names.empty() ? "" : " or ") + sub->get_name();
    return fmt::format("'{}' needs a subcommand: {}{}", deepest->get_name(), names,
                       unexpected.empty() ? std::string() : ", got " + dfvn::quote_for_message(unexpected.front()));
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error) && !unexpected.empty()) {
    std::string list;
    for (const std::string& arg : unexpected) list += (list.empty() ? "" : " ") + dfvn::quote_for_message(arg);
    return fmt::format("unexpected argument{}: {}", unexpected.size() > 1 ? "s" : "", list);
  }
  return error.what();
}

// 'sample' is the default: insert it when the first argument names no subcommand and is not one of
// the program's own flags (--help, --help-all, --version).
std::vector<std::string> with_default_subcommand(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool names_subcommand = !args.empty() && std::find(kSubcommands.begin(), kSubcommands.end(), args[0]) != kSubcommands.end();
  const bool top_level_flag =
      !args.empty() && (args[0] == "--version" || args[0] == "--help-all" || args[0] == "--help" || args[0] == "-h");
  if (!names_subcommand && !top_level_flag) args.insert(args.begin(), "sample");
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  return args;
}

// --help-all: the help of `app` and then of every subcommand below it, depth first (CLI11's own lists
// only the first level's options and leaves out reproduce's subcommands). Each subcommand's help is
// indented under a line "dfvn-sample reproduce table1:", which help2man makes a section of the man page.
std::string complete_help(CLI::App& app) {
  // CLI11 names a subcommand in its usage line by the path it is given ("dfvn-sample reproduce").
  std::string parents;
  for (const CLI::App* p = app.get_parent(); p != nullptr; p = p->get_parent())
    parents = p->get_name() + (parents.empty() ? "" : " " + parents);
  std::string text = app.help(parents, CLI::AppFormatMode::Normal);
  const CLI::App* root = &app;
  while (root->get_parent() != nullptr) root = root->get_parent();
  const std::string footer = root->get_footer();
  const std::function<void(CLI::App&, const std::string&)> add = [&](CLI::App& parent, const std::string& path) {
    for (CLI::App* sub : parent.get_subcommands([](CLI::App*) { return true; })) {
      const std::string name = path + " " + sub->get_name();
      text += "\n" + name + ":\n";
      std::string help = sub->help(path, CLI::AppFormatMode::Normal);
      // The program's footer, which every subcommand inherits, is printed once, at the top.
      if (const std::size_t at = help.rfind(footer); !footer.empty() && at != std::string::npos) help.erase(at);
      while (help.size() >= 2 && help.substr(help.size() - 2) == "\n\n") help.pop_back();
      for (const std::string& line : CLI::detail::split(help, '\n')) text += line.empty() ? "\n" : "  " + line + "\n";
      add(*sub, name);
    }
  };
  add(app, parents.empty() ? app.get_name() : parents + " " + app.get_name());
  return text;
}

// Without arguments: what the tool does and how to start, instead of starting a long job.
constexpr const char* kUsageText =
    "dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions, curl noise jittering of lattices\n"
    "and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).\n"
    "\n"
    "The main job: CNJ, jittered lattice, Poisson disk and Sobol point sets and one CSV row of\n"
    "nearest-neighbour statistics per method (any options run it, as does 'dfvn-sample sample ...'):\n"
    "  dfvn-sample --dim 7 --grid 6              the paper's 7D sets (about a minute on 2 cores)\n"
    "  dfvn-sample -d 3 -n 4096 -o stats.csv     3D, 4096 points per set\n"
    "\n"
    "Subcommands:\n"
    "  sample      the main job (the default)\n"
    "  field       evaluate the field at points read as text\n"
    "  stats       statistics of any point set (CSV, NPY or dat)\n"
    "  animate     CNJ animated as the field's phase turns: frames, their counts, a strip figure\n"
    "  reproduce   the paper's tables and figures: table1, table2, cnj-study, integration, figure8\n"
    "\n"
    "'dfvn-sample SUBCOMMAND --help' lists a subcommand's options and defaults; --help-all lists every one;\n"
    "--version prints the version.\n";

// The usage and the list of methods (--methods), from dfvn::kAllMethods.
std::string usage() {
  std::string text = kUsageText;
  const std::string marker = "\nSubcommands:";
  text.insert(text.find(marker), "  methods (--methods): " + dfvn::method_names() + "\n");
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 1) {
    std::fputs(usage().c_str(), stdout);
    return 0;
  }
  CLI::App app{"dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions: the field, curl-noise\n"
               "jittering of lattices, and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).",
               kProgram};
  app.set_version_flag("--version", std::string(kProgram) + " " + DFVN_VERSION);
  app.set_help_all_flag("--help-all", "Print the help of every subcommand and exit");
  app.require_subcommand(1);
  app.footer("Without a subcommand, 'sample' runs (the main job): 'dfvn-sample --dim 7 --grid 6'.\n"
             "Each subcommand has --help: 'dfvn-sample sample --help', 'dfvn-sample reproduce table1 --help'.");
  const auto sample = dfvn_cli::add_sample_command(app);
  const auto field = dfvn_cli::add_field_command(app);
  const auto reproduce = dfvn_cli::add_reproduce_command(app);
  const auto stats = dfvn_cli::add_stats_command(app);
  const auto animate = dfvn_cli::add_animate_command(app);

  dfvn::remove_temporaries_on_signals();
  const std::vector<std::string> given(argv + 1, argv + argc);
  try {
    std::vector<std::string> args = with_default_subcommand(argc, argv);
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp&) {
    std::fputs(complete_help(*deepest_subcommand(app)).c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fail(with_safe_echoes(parse_error_message(app, e), given) + " (run with --help for the options)", 2);
  } catch (const std::bad_alloc& e) {  // the library names what it allocates where it can; this is the rest
    fail(dynamic_cast<const dfvn::OutOfMemory*>(&e) ? e.what() : "out of memory; try a smaller problem");
  } catch (const std::exception& e) {
    fail(e.what());
  }
  return 0;
}
