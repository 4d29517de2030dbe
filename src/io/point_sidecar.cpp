#include "dfvn/io/point_sidecar.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

namespace {
constexpr const char* kFormat = "dfvn-sample point set";
constexpr int kVersion = 1;
}  // namespace

std::string point_sidecar_path(const std::string& point_file) { return point_file == "-" ? std::string() : point_file + ".json"; }

std::string point_sidecar_json(const Domain& domain, int dimension, const std::vector<std::uint64_t>& points_per_set,
                               const std::string& made_by) {
  nlohmann::ordered_json out;
  out["format"] = kFormat;
  out["version"] = kVersion;
  out["dimension"] = dimension;
  out["sets"] = points_per_set.size();
  out["points"] = points_per_set;
  out["domain"] = {{"kind", to_string(domain.kind)}, {"lo", domain.lo}, {"side", domain.side}, {"periodic", domain.periodic()}};
  if (!made_by.empty()) out["made_by"] = nlohmann::ordered_json::parse(made_by);
  return out.dump(2) + "\n";
}

std::optional<Domain> read_point_sidecar_domain(const std::string& point_file, int dimension) {
  const std::string path = point_sidecar_path(point_file);
  struct stat status {};
  if (path.empty() || ::stat(path.c_str(), &status) != 0) return std::nullopt;
  const std::string name = quote_for_message(path, kMaxPathEchoChars);
  if (!S_ISREG(status.st_mode)) throw std::invalid_argument("the sidecar " + name + " is not a regular file");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw std::invalid_argument("cannot read the sidecar " + name);
  const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
  const auto fail = [&](const std::string& why) -> std::invalid_argument {
    return std::invalid_argument("the sidecar " + name + " " + why + " (delete it, or give --domain and --domain-side)");
  };
  if (json.is_discarded() || !json.is_object()) throw fail("is not JSON");
  if (json.value("format", std::string()) != kFormat) throw fail("is not a dfvn-sample point-set description");
  if (!json.contains("version") || !json["version"].is_number_integer() || json["version"].get<int>() != kVersion)
    throw fail("has another version than 1");
  if (dimension != 0 && json.contains("dimension") && json["dimension"].is_number_integer() &&
      json["dimension"].get<int>() != dimension)
    throw fail("describes " + std::to_string(json["dimension"].get<int>()) + "D points, not the file's " +
               std::to_string(dimension) + "D");
  const nlohmann::json& d = json.contains("domain") ? json["domain"] : nlohmann::json();
  if (!d.is_object() || !d.contains("kind") || !d["kind"].is_string() || !d.contains("lo") || !d["lo"].is_number() ||
      !d.contains("side") || !d["side"].is_number())
    throw fail("has no domain {kind, lo, side}");
  Domain domain;
  try {
    domain.kind = parse_domain_kind(d["kind"].get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw fail(std::string("names ") + e.what());
  }
  domain.lo = d["lo"].get<double>();
  domain.side = d["side"].get<double>();
  if (!std::isfinite(domain.lo) || !std::isfinite(domain.side) || !(domain.side > 0.0))
    throw fail("has a domain without a finite lower corner and a positive side");
  return domain;
}

}  // namespace dfvn
