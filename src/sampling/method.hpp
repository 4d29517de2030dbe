// The names of the generators (methods) and of the lattice protocols; defined in sampling/lattice.cpp.
#pragma once

#include <string>
#include <string_view>

namespace dfvn {

// jitter_matched: jitter whose RMS displacement equals CNJ's in the same run (sampling/jitter.hpp).
enum class Method { cnj, jitter, jitter_matched, pds, sobol, random, halton, lhs };
inline constexpr Method kAllMethods[] = {Method::cnj,   Method::jitter, Method::jitter_matched, Method::pds,
                                         Method::sobol, Method::random, Method::halton,         Method::lhs};
Method parse_method(std::string_view name);  // throws std::invalid_argument listing the names
std::string_view to_string(Method method);
std::string method_names();  // "cnj, jitter, jitter-matched, ..."

// fair (the main job's): every method in the run's one domain (core/domain.hpp: the unit torus, cube,
// ball or sphere) at one count, the K^N sites of a cell-centred lattice in it (its spacing 1/K), measured
// in that domain's metric. paper: Section 5.1 exactly as data/PROTOCOL.md establishes it, for every
// method: the paper's lattice, boxes and densities in the cube, Euclidean distances.
enum class Protocol { fair, paper };
Protocol parse_protocol(std::string_view name);
std::string_view to_string(Protocol protocol);

}  // namespace dfvn
