#include "help_format.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>
#include <string_view>
#include <vector>

namespace dfvn_cli {
namespace {

// The value's name in the help, for options whose description names it by a letter (K, C, R, ...);
// the others are named after the last word of their long name (--rdf-bins BINS).
const std::map<std::string, std::string, std::less<>> kValueNames = {
    {"dim", "N"},          {"grid", "K"},          {"count", "COUNT"},           {"seed", "S"},
    {"threads", "T"},      {"sets", "R"},          {"realizations", "R"},        {"steps", "M"},
    {"step-scale", "C"},   {"step-scales", "C"},   {"cycles-per-spacing", "C"},  {"frequency", "F"},
    {"phase", "A"},        {"phase-step", "DA"},   {"rdf-max", "R"},             {"rdf-bins", "B"},
    {"rdf-queries", "Q"},  {"pds-radius", "R"},    {"pds-candidates", "K"},      {"max-memory", "GIB"},
    {"slabs", "S"},        {"reproject-iters", "R"}, {"boundary-spacings", "W"}, {"boundary-width", "W"},
    {"domain-side", "S"},  {"width", "W"},         {"height", "H"},              {"frames", "F"},
    {"drop-margin", "M"},  {"trace-time", "T"},    {"rk4-steps", "M"},           {"segments", "S"},
    {"image", "S"},        {"octaves", "K"},       {"octave-gain", "G"},         {"steer-k", "K"},
    {"steer-quality", "Q"}, {"methods", "LIST"},   {"dims", "LIST"},             {"noises", "LIST"},
    {"out", "DIR"},        {"output", "FILE"},     {"input", "FILE"},            {"json", "FILE"},
    {"rdf", "FILE"},       {"report", "FILE"},     {"summary", "FILE"},          {"points", "PATH"},
    {"spectrum", "PREFIX"}, {"obstacle", "SPEC"},  {"lattice-3d", "L"},          {"slope", "SX,SY"},
    {"bump", "H,R"},       {"samples", "S"},       {"realization", "R"},
};

const std::vector<std::string> kBaseTypes = {"INT", "UINT", "FLOAT", "TEXT", "BOOLEAN", "UINT64"};

// A number as the help shows it: integers whole, powers of two named, others to 6 digits.
std::string number_text(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) return text;
  if (value == static_cast<double>(static_cast<long long>(value)) && std::abs(value) < 1e15)
    return fmt::format("{}", static_cast<long long>(value));
  return fmt::format("{:g}", value);
}

// What a validator's description says about the allowed values, in the help's words; empty when it
// says nothing a reader needs (a finite real).
std::string allowed_values(const std::string& validator) {
  static const std::regex range(R"((?:INT|UINT|FLOAT) in \[(.*) - (.*)\])");
  std::smatch m;
  if (std::regex_match(validator, m, range)) {
    const double high = std::strtod(m[2].str().c_str(), nullptr);
    const double low = std::strtod(m[1].str().c_str(), nullptr);
    if (high >= 1e6 && low > 0.0 && low < 1e-300) return "> 0";
    if (high >= 1e6) return ">= " + number_text(m[1].str());
    return number_text(m[1].str()) + ".." + number_text(m[2].str());
  }
  if (validator == "POSITIVE") return "> 0";
  if (validator == "NONNEGATIVE") return ">= 0";
  if (validator == "FREQUENCY") return "2^-50..2^50";
  if (validator == "SIDE") return "2^-1000..2^1000";
  if (validator == "UINT64") return "0..2^64-1";
  if (validator == "THREADS") return "0 = all cores";
  return {};
}

bool is_choice_list(const std::string& validator) { return validator.size() > 2 && validator.front() == '{'; }

std::string last_word(const std::string& name) {
  std::string word = name.substr(name.rfind('-') + 1);
  for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return word;
}

}  // namespace

std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width) {
  std::string out;
  const std::string pad(indent, ' ');
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find("\n\n", start);
    if (end == std::string::npos) end = text.size();
    std::istringstream words(text.substr(start, end - start));
    std::string word, line;
    while (words >> word) {
      if (!line.empty() && pad.size() + line.size() + 1 + word.size() > width) {
        out += pad + line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) out += pad + line + "\n";
    if (end >= text.size()) break;
    out += "\n";
    start = end + 2;
  }
  return out;
}

std::string summary_of(const CLI::App& app) {
  const std::string& description = app.get_description();
  return description.substr(0, description.find("\n\n"));
}

std::string HelpFormatter::make_option_name(const CLI::Option* opt, bool is_positional) const {
  if (is_positional) return opt->get_name(true, false);
  std::string names;
  for (const std::string& s : opt->get_snames()) names += (names.empty() ? "-" : ", -") + s;
  for (const std::string& l : opt->get_lnames()) names += (names.empty() ? "--" : ", --") + l;
  return names;
}

// ` N (2..8, default 7)`: the value's name, or its choices, then what is allowed and the default.
std::string HelpFormatter::make_option_opts(const CLI::Option* opt) const {
  if (opt->get_type_size() == 0 || opt->get_type_name().empty()) return {};  // a flag
  std::vector<std::string> parts = CLI::detail::split(opt->get_type_name(), ':');
  std::string value_name;
  std::vector<std::string> notes;
  std::string choices;
  const bool base_type = !parts.empty() && std::find(kBaseTypes.begin(), kBaseTypes.end(), parts[0]) != kBaseTypes.end();
  std::size_t first_validator = 1;
  if (!base_type && !parts.empty()) {
    value_name = parts[0];
    // A name with a colon of its own (U:S): the parts in capitals that no validator describes.
    while (first_validator < parts.size() && parts[first_validator].size() <= 2 &&
           allowed_values(parts[first_validator]).empty() && !is_choice_list(parts[first_validator]))
      value_name += ":" + parts[first_validator++];
  }
  for (std::size_t i = first_validator; i < parts.size(); ++i) {
    if (is_choice_list(parts[i]))
      choices = parts[i];
    else if (const std::string allowed = allowed_values(parts[i]); !allowed.empty())
      notes.push_back(allowed);
  }
  const std::string long_name = opt->get_lnames().empty() ? opt->get_name() : opt->get_lnames().front();
  if (value_name.empty() || value_name == "FILE|-") {
    const auto known = kValueNames.find(long_name);
    value_name = known != kValueNames.end() ? known->second : last_word(long_name);
  }
  std::string text = " " + (choices.empty() ? value_name : choices);
  const bool repeatable = opt->get_expected_max() >= CLI::detail::expected_max_vector_size;
  if (repeatable) text += "...";
  std::string default_text = opt->get_default_str();
  if (!default_text.empty() && default_text.front() == '[' && default_text.back() == ']')
    default_text = default_text.substr(1, default_text.size() - 2);
  if (!default_text.empty()) {
    std::string shown;
    for (const std::string& item : CLI::detail::split(default_text, ','))
      shown += (shown.empty() ? "" : ",") + number_text(item);
    notes.push_back("default " + shown);
  }
  if (opt->get_required()) notes.push_back("required");
  if (!notes.empty()) {
    std::string joined;
    for (const std::string& note : notes) joined += (joined.empty() ? "" : ", ") + note;
    text += " (" + joined + ")";
  }
  return text;
}

std::string HelpFormatter::make_option_usage(const CLI::Option* opt) const {
  // A positional that is also an option (stats' files) is shown by its option's value name.
  if (!opt->get_lnames().empty()) return "[" + kValueNames.at(opt->get_lnames().front()) + "...]";
  return CLI::Formatter::make_option_usage(opt);
}

// Positionals that are also options (stats' --input) are listed once, with the option.
std::string HelpFormatter::make_positionals(const CLI::App* app) const {
  std::vector<const CLI::Option*> opts = app->get_options(
      [](const CLI::Option* opt) { return !opt->get_group().empty() && opt->get_positional() && opt->get_lnames().empty(); });
  if (opts.empty()) return {};
  return make_group(get_label("Positionals"), true, opts);
}

// The names and the value on one line, the description wrapped below it.
// (A heading too long for the width keeps its value there and starts the description with the notes.)
std::string HelpFormatter::make_option(const CLI::Option* opt, bool is_positional) const {
  std::string heading = "  " + make_option_name(opt, is_positional) + make_option_opts(opt);
  std::string description = make_option_desc(opt);
  if (heading.size() > kHelpWidth && heading.back() == ')') {
    const std::size_t notes = heading.rfind(" (");
    description = heading.substr(notes + 2, heading.size() - notes - 3) + ". " + description;
    description[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(description[0])));
    heading.erase(notes);
  }
  return heading + "\n" + wrap_text(description, 6);
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  constexpr std::size_t kNameColumn = 14;
  std::string name = "  " + sub->get_name();
  std::string summary = wrap_text(summary_of(*sub), kNameColumn);
  if (name.size() < kNameColumn) summary.replace(0, name.size(), name);
  else summary = name + "\n" + summary;
  return summary;
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string& description = app->get_description();
  return description.empty() ? std::string() : wrap_text(description, 0) + "\n";
}

void use_help_format(CLI::App& app) { app.formatter(std::make_shared<HelpFormatter>()); }

}  // namespace dfvn_cli
