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
#include "help_format.hpp"
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

// Typos get one suggestion: the closest name by edit distance (apps/options.hpp's closest_names), or
// the tied closest names; a name far from every one gets none.
std::string did_you_mean(const std::vector<std::string>& closest) {
  std::string text;
  for (std::size_t i = 0; i < closest.size(); ++i) text += (i == 0 ? "" : i + 1 == closest.size() ? " or " : ", ") + closest[i];
  return closest.empty() ? std::string() : "; did you mean " + text + "?";
}

// The option names a subcommand takes (its hidden, refused names left out).
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_group().empty()) continue;
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : const_cast<CLI::App&>(app).get_subcommands([](CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// A parse error as the tool's own line: unexpected arguments in the order given (a mistyped option or
// subcommand with the name it was probably meant to be), and a missing subcommand with the names it
// could have been.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& error, const std::vector<std::string>& given) {
  CLI::App* deepest = deepest_subcommand(app);
  const std::vector<std::string> unexpected = app.remaining(true);
  if (deepest->get_require_subcommand_min() > 0 && deepest->get_subcommands().empty()) {
    if (!unexpected.empty()) {
      const auto closest = dfvn_cli::closest_names(unexpected.front(), subcommand_names(*deepest));
      if (!closest.empty())
        return fmt::format("unknown {} subcommand {}{}", deepest->get_name(), dfvn::quote_for_message(unexpected.front()),
                           did_you_mean(closest));
    }
    std::string names;
    for (const std::string& name : subcommand_names(*deepest)) names += (names.empty() ? "" : " or ") + name;
    return fmt::format("'{}' needs a subcommand: {}{}", deepest->get_name(), names,
                       unexpected.empty() ? std::string() : ", got " + dfvn::quote_for_message(unexpected.front()));
  }
  // A mistyped option explains the error, whatever CLI11 found first (a required option missing, say).
  if (!unexpected.empty() && unexpected.front().starts_with("-")) {
    const std::string& first = unexpected.front();
    const std::string name = first.substr(0, first.find('='));
    const auto closest = dfvn_cli::closest_names(name, option_names(*deepest));
    if (!closest.empty()) {
      const bool named = deepest != &app && std::find(given.begin(), given.end(), deepest->get_name()) != given.end();
      return "unknown option " + dfvn::quote_for_message(name) + (named ? " for " + deepest->get_name() : std::string()) +
             did_you_mean(closest);
    }
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error) && !unexpected.empty()) {
    const std::string& first = unexpected.front();
    // The first word names no subcommand (sample ran by default): a mistyped subcommand?
    if (!given.empty() && given.front() == first && !first.starts_with("-")) {
      const auto closest = dfvn_cli::closest_names(first, subcommand_names(app));
      if (!closest.empty()) return "unknown subcommand " + dfvn::quote_for_message(first) + did_you_mean(closest);
    }
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

// Without arguments: what the tool does and how to start, instead of starting a long job. The
// subcommands, reproduce's list and the methods come from the registered subcommands and
// dfvn::kAllMethods, as --help, --help-all, the man page and the completion do. The main job's time was
// measured on 2 cores with AVX-512 (docs/PERFORMANCE.md: 16 s wall at load 4, 23.5 s CPU, 2026-11-28).
std::string usage(CLI::App& app) {
  std::string text =
      "dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions, curl noise jittering of lattices\n"
      "and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).\n"
      "\n"
      "The main job: every method's point set in one domain at one count, and one CSV row of\n"
      "nearest-neighbour statistics per method (any options run it, as does 'dfvn-sample sample ...'):\n"
      "  dfvn-sample --dim 7 --grid 6              7D, 6^7 points a set (7-8 s on 2 cores)\n"
      "  dfvn-sample -d 3 -n 4096 -o stats.csv     3D, 4096 points a set, the statistics to a file\n"
      "  methods (--methods): " + dfvn::method_names() + "\n"
      "\n"
      "Subcommands:\n";
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    std::string line = fmt::format("  {:<12}{}", sub->get_name(), dfvn_cli::summary_of(*sub));
    const auto children = sub->get_subcommands([](CLI::App*) { return true; });
    if (!children.empty()) {
      std::string names;
      for (const CLI::App* child : children) names += (names.empty() ? "" : ", ") + child->get_name();
      line += ":\n" + dfvn_cli::wrap_text(names, 14);
      line.pop_back();
    }
    text += line + "\n";
  }
  return text +
         "\n"
         "'dfvn-sample SUBCOMMAND --help' lists a subcommand's options and defaults; --help-all lists every one;\n"
         "--version prints the version.\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dfvn-sample: divergence-free vector noise (DFVN) in 2..8 dimensions: the field, curl-noise\n"
               "jittering of lattices, and the point-set statistics of 'Improving Curl Noise' (SIGGRAPH Asia 2025).",
               kProgram};
  dfvn_cli::use_help_format(app);
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
  if (argc == 1) {
    std::fputs(usage(app).c_str(), stdout);
    return 0;
  }

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
    fail(with_safe_echoes(parse_error_message(app, e, given), given) + " (run with --help for the options)", 2);
  } catch (const std::bad_alloc& e) {  // the library names what it allocates where it can; this is the rest
    fail(dynamic_cast<const dfvn::OutOfMemory*>(&e) ? e.what() : "out of memory; try a smaller problem");
  } catch (const std::exception& e) {
    fail(e.what());
  }
  return 0;
}
