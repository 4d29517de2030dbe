// The description that travels with a point file: a small JSON file beside it, <file>.json
// (e.g. cnj.npy.json), saying where the points live (the domain's kind, lower corner and side, whether
// it is periodic), how many there are, and what made them (the program, method, seed, protocol and
// settings). `dfvn-sample stats` reads it, so that a file is measured again in the domain it was made
// in; other tools read the point file itself unchanged (UTK's .dat/.bin, NumPy's .npy).
#pragma once

#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "dfvn/core/domain.hpp"

namespace dfvn {

// "<point file>.json"; none for standard output ("-").
std::string point_sidecar_path(const std::string& point_file);

// The sidecar's text: {"format": "dfvn-sample point set", "version": 1, "dimension": ..., "sets": ...,
// "points": [one count per set], "domain": {"kind", "lo", "side", "periodic"}, "made_by": <made_by>},
// where made_by is a JSON object's text (the generator's settings, experiment/json_report.hpp) or empty.
std::string point_sidecar_json(const Domain& domain, int dimension, const std::vector<std::uint64_t>& points_per_set,
                               const std::string& made_by);

// The domain a point file's sidecar names, or nullopt when the file has none. Throws
// std::invalid_argument, naming the sidecar, when it exists but cannot be read as one (malformed JSON,
// another format, a domain kind or side that is not valid), or describes another dimension than
// `dimension` (0: not checked).
std::optional<Domain> read_point_sidecar_domain(const std::string& point_file, int dimension = 0);

}  // namespace dfvn
