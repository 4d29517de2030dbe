// A point set and the domain it lives in: the type every floor above core shares (generators make
// it, evaluators and the point files read it).
#pragma once

#include <cstddef>
#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/domain.hpp"

namespace dfvn {

// points: size() x dimension, row-major. Coordinates(n) leaves its numbers unwritten (core/bulk_memory.hpp):
// whoever sizes it writes every one. `domain`: where the points live, which decides how they are
// measured (the torus' minimum-image distances, the cube's edge correction, the density's volume).
struct PointSet {
  int dimension = 0;
  Coordinates coordinates;
  Domain domain;
  std::size_t size() const { return dimension ? coordinates.size() / dimension : 0; }
  const double* point(std::size_t i) const { return coordinates.data() + i * dimension; }
};

}  // namespace dfvn
