#include "dfvn/experiment/json_report.hpp"

#include <algorithm>

#include <map>

#include <nlohmann/json.hpp>

#include "dfvn/experiment/realizations.hpp"

namespace dfvn {

namespace {

using nlohmann::ordered_json;

// JSON text is Unicode: a string that is not valid UTF-8 (a file name with the byte 0xFF) has each
// invalid byte written as U+FFFD, where nlohmann's default threw its own exception text.
std::string dump(const ordered_json& value) {
  return value.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

template <typename T>
void put_if(ordered_json& object, const char* key, const std::optional<T>& value) {
  if (value) object[key] = *value;
}

ordered_json nearest_json(const NearestNeighbourSummary& s) {
  return {{"min", s.min}, {"q01", s.q01}, {"median", s.median}, {"mean", s.mean}, {"median_scaled", s.median_scaled}};
}

ordered_json displacement_json(const LatticeDisplacementSummary& d) {
  return {{"rms", d.rms},
          {"median", d.median},
          {"frac_unmoved", d.fraction_unmoved},
          {"neighbour_disorder", d.neighbour_disorder},
          {"lattice_order", d.lattice_order}};
}

// Every number of every group's objects (by the key path "object.key") that varies, summarised as
// mean, sd and standard error, in
// the order the keys first appear.
ordered_json summary_json(const std::vector<std::pair<std::string, ordered_json>>& members) {
  std::vector<std::string> groups;
  std::map<std::string, std::vector<std::string>> keys;
  std::map<std::string, std::map<std::string, std::vector<double>>> values;
  for (const auto& [group, object] : members) {
    if (!values.contains(group)) groups.push_back(group);
    auto& group_values = values[group];
    for (const auto& [section, content] : object.items()) {
      if (!content.is_object() || section == "domain" || section == "seconds") continue;
      for (const auto& [key, value] : content.items()) {
        if (!value.is_number()) continue;
        const std::string path = section + "." + key;
        if (!group_values.contains(path)) keys[group].push_back(path);
        group_values[path].push_back(value.get<double>());
      }
    }
  }
  ordered_json summary = ordered_json::object();
  for (const std::string& group : groups) {
    ordered_json entry = ordered_json::object();
    for (const std::string& path : keys[group]) {
      const std::vector<double>& v = values[group][path];
      // A value constant over the realizations (a setting) is not summarised, as in --summary's CSV; the
      // sets' statistics always are.
      const bool statistic = path.starts_with("nearest_neighbour.") || path.starts_with("displacement.") ||
                             path.starts_with("discrepancy.");
      if (!statistic && std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); })) continue;
      const MeanSd s = mean_sd(v);
      entry[path] = {{"mean", s.mean}, {"sd", s.sd}, {"standard_error", standard_error(s, values[group][path].size())}};
    }
    summary[group] = std::move(entry);
  }
  return summary;
}

// A report's head: the program, its version and the run's parameters, in that order.
ordered_json report_head(ordered_json parameters) {
  ordered_json out;
  out["program"] = "dfvn-sample";
  out["version"] = DFVN_VERSION;
  out["parameters"] = std::move(parameters);
  return out;
}

}  // namespace

namespace {

ordered_json generation_json(const GenerationFacts& f) {
  ordered_json generation = ordered_json::object();
  put_if(generation, "cycles_per_spacing", f.frequency);
  put_if(generation, "field_frequency", f.field_frequency);
  put_if(generation, "trace_time", f.trace_time);
  put_if(generation, "dropped", f.dropped);
  put_if(generation, "skipped_updates", f.skipped_updates);
  put_if(generation, "retraced", f.retraced);
  put_if(generation, "kept_at_site", f.kept_at_site);
  put_if(generation, "half_width", f.half_width);
  put_if(generation, "radius", f.radius);
  put_if(generation, "saturated", f.saturated);
  return generation;
}

ordered_json sampling_parameters(const SampleConfig& config, const std::vector<SamplingRealization>& realizations);

}  // namespace

std::string point_set_made_by_json(const SampleConfig& config, const MethodResult& result,
                                   const std::vector<std::uint64_t>& seeds) {
  ordered_json out;
  out["program"] = "dfvn-sample";
  out["version"] = DFVN_VERSION;
  out["method"] = to_string(result.plan.method);
  out["protocol"] = to_string(config.protocol);
  out["seeds"] = seeds;
  out["requested"] = result.plan.requested;
  out["generation"] = generation_json(result.facts);
  out["notes"] = result.notes;
  SamplingRealization one{seeds.empty() ? config.seed : seeds.front(), {}};
  out["run"] = sampling_parameters(config, {one});
  return out.dump(-1, ' ', false, ordered_json::error_handler_t::replace);
}

std::string sampling_json(const SampleConfig& config, const std::vector<SamplingRealization>& realizations, bool timing) {
  ordered_json parameters = sampling_parameters(config, realizations);
  ordered_json results = ordered_json::array();
  std::vector<std::pair<std::string, ordered_json>> members;
  for (const SamplingRealization& realization : realizations) {
    for (const MethodResult& r : realization.results) {
      ordered_json entry;
      entry["method"] = to_string(r.plan.method);
      entry["seed"] = realization.seed;
      entry["requested"] = r.plan.requested;
      entry["points"] = r.point_count;
      entry["domain"] = {{"kind", to_string(r.plan.domain.kind)}, {"lo", r.plan.domain.lo}, {"side", r.plan.domain.side}};
      entry["nearest_neighbour"] = r.measured ? nearest_json(r.nearest) : ordered_json(nullptr);
      entry["displacement"] = r.displacement ? displacement_json(*r.displacement) : ordered_json(nullptr);
      entry["generation"] = generation_json(r.facts);
      if (timing) {
        entry["seconds"] = {{"generate", r.seconds_generate}};
        if (r.measured) entry["seconds"]["stats"] = r.seconds_stats;
      }
      entry["notes"] = r.notes;
      members.emplace_back(entry["method"].get<std::string>(), entry);
      results.push_back(std::move(entry));
    }
  }
  ordered_json out = report_head(std::move(parameters));
  out["results"] = std::move(results);
  if (realizations.size() > 1) out["summary"] = summary_json(members);
  return dump(out);
}

namespace {

ordered_json sampling_parameters(const SampleConfig& config, const std::vector<SamplingRealization>& realizations) {
  ordered_json parameters;
  parameters["dim"] = config.dimension;
  parameters["grid"] = config.grid;
  parameters["lattice_points"] = config.lattice().point_count();
  parameters["count"] = config.count > 0 ? ordered_json(config.count) : ordered_json(nullptr);
  parameters["seed"] = realizations.empty() ? config.seed : realizations.front().seed;
  parameters["realizations"] = realizations.size();
  ordered_json methods = ordered_json::array();
  for (Method m : config.methods) methods.push_back(to_string(m));
  parameters["methods"] = methods;
  parameters["protocol"] = to_string(config.protocol);
  parameters["knn"] = to_string(config.knn);
  parameters["scramble"] = to_string(config.scramble);
  parameters["statistics"] = config.compute_statistics;
  parameters["cnj"] = {{"noise", to_string(config.cnj.noise)},
                       {"integrator", to_string(config.cnj.trace.integrator)},
                       {"steps", cnj_steps(config.domain() == DomainKind::sphere ? sphere_cnj_options(config.cnj) : config.cnj)},
                       {"step_scale", config.cnj.step_scale},
                       {"cycles_per_spacing", config.cnj.frequency},
                       {"reprojection", to_string(config.cnj.trace.reprojection)},
                       {"reproject_iterations", config.cnj.trace.reproject_iterations},
                       {"domain", to_string(config.cnj.domain)},
                       {"domain_mode", to_string(config.cnj.domain_mode)},
                       {"bound", to_string(config.cnj.bound)},
                       {"boundary_spacings", config.cnj.boundary_width}};
  // Only when not the default, so that --field dfvn's report keeps today's bytes.
  if (config.cnj.field != kDefaultFieldKind) parameters["cnj"]["field"] = to_string(config.cnj.field);
  // Only a phase other than 0 is recorded, so that a phase-free run's report stays what it was.
  if (config.cnj.phase != 0.0) parameters["cnj"]["phase"] = config.cnj.phase;
  // The noise transforms likewise, each only when given.
  const NoiseTransform& transform = config.cnj.transform;
  if (!transform.stretch_direction.empty())
    parameters["cnj"]["stretch"] = {{"direction", transform.stretch_direction}, {"factor", transform.stretch_factor}};
  if (transform.time) parameters["cnj"]["time"] = *transform.time;
  if (transform.lift.active())
  {
    const LiftSpec::Kind kind = transform.lift.kind;
    parameters["cnj"]["lift"] = {{"height", kind == LiftSpec::Kind::plane ? "plane" : kind == LiftSpec::Kind::bump ? "bump" : "npy"},
                                 {"parameters", transform.lift.parameters},
                                 {"ramp", transform.lift.ramp}};
    if (kind == LiftSpec::Kind::npy) parameters["cnj"]["lift"]["file"] = transform.lift.path;
  }
  if (transform.steer.active())
    parameters["cnj"]["steer"] = {{"field", transform.steer.circular ? "circular" : "constant"},
                                  {"direction", transform.steer.direction},
                                  {"k", transform.steer.k}};
  parameters["domain"] = to_string(config.domain());
  parameters["periodic_statistics"] = config.periodic_statistics();
  // null: the protocol's radius (paper) or the one found (fair), which each pds result gives under "generation".
  parameters["pds"] = {{"radius", config.pds_radius > 0.0 ? ordered_json(config.pds_radius) : ordered_json(nullptr)},
                       {"candidates", config.pds_candidates}};
  parameters["rdf"] = config.compute_rdf ? ordered_json{{"r_max", config.rdf.r_max}, {"bins", config.rdf.bins},
                                                        {"max_queries", config.rdf.max_queries}}
                                         : ordered_json(nullptr);
  return parameters;
}

}  // namespace

std::string point_statistics_json(const PointStatisticsRun& run) {
  ordered_json parameters = {{"input", run.input},
                             {"format", run.format},
                             {"domain_side", run.domain_side},
                             {"knn", to_string(run.options.knn)},
                             {"discrepancy", run.options.discrepancy}};
  ordered_json sets = ordered_json::array();
  std::vector<std::pair<std::string, ordered_json>> members;
  for (std::size_t s = 0; s < run.sets.size(); ++s) {
    const PointSetStatistics& statistics = run.sets[s];
    ordered_json entry;
    entry["set"] = s;
    entry["dim"] = run.dimensions.at(s);
    entry["points"] = statistics.nearest.points;
    entry["nearest_neighbour"] = nearest_json(statistics.nearest);
    ordered_json discrepancies = ordered_json::object();
    for (std::size_t d = 0; d < std::size(kAllDiscrepancies); ++d)
      if (statistics.discrepancies[d]) discrepancies[std::string(csv_column(kAllDiscrepancies[d]))] = *statistics.discrepancies[d];
    entry["discrepancy"] = run.options.discrepancy ? discrepancies : ordered_json(nullptr);
    if (run.timing) entry["seconds"] = {{"stats", statistics.seconds}};
    members.emplace_back("all", entry);
    sets.push_back(std::move(entry));
  }
  ordered_json out = report_head(std::move(parameters));
  out["sets"] = std::move(sets);
  if (run.sets.size() > 1) out["summary"] = summary_json(members)["all"];
  return dump(out);
}

}  // namespace dfvn
