// The help layout of dfvn-sample and dfvn-sample-mpi: short value labels built from each option's own
// declaration (its type, range or choices and default: `-d, --dim N (2..8, default 7)`), descriptions
// wrapped under the option within 100 columns, and a subcommand's one-line summary (its description's
// first paragraph) in the lists. --help, --help-all, the no-argument usage, the man page (help2man reads
// --help-all) and the bash completion (it reads --help) all come from this one text.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace dfvn_cli {

// Help lines stay within this many columns; --help-all indents a subcommand's help by 2 more.
inline constexpr std::size_t kHelpWidth = 98;

class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option(const CLI::Option* opt, bool is_positional) const override;
  std::string make_option_name(const CLI::Option* opt, bool is_positional) const override;
  std::string make_option_opts(const CLI::Option* opt) const override;
  std::string make_option_usage(const CLI::Option* opt) const override;
  std::string make_positionals(const CLI::App* app) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
  std::string make_description(const CLI::App* app) const override;
};

// Installs HelpFormatter on `app` (subcommands added later inherit it).
void use_help_format(CLI::App& app);

// A subcommand's one-line summary: the first paragraph of its description.
std::string summary_of(const CLI::App& app);

// `text` re-wrapped to `width` columns, every line indented by `indent` spaces; paragraphs (blank lines)
// are kept, the lines within one are joined.
std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width = kHelpWidth);

}  // namespace dfvn_cli
