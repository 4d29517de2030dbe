#include "dfvn/core/domain.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

DomainKind parse_domain_kind(std::string_view name) {
  for (DomainKind kind : kAllDomainKinds)
    if (name == to_string(kind)) return kind;
  throw std::invalid_argument("unknown domain " + quote_for_message(name) + " (allowed: " + domain_kind_names() + ")");
}

std::string_view to_string(DomainKind kind) {
  switch (kind) {
    case DomainKind::torus: return "torus";
    case DomainKind::cube: return "cube";
    case DomainKind::ball: return "ball";
    case DomainKind::sphere: return "sphere";
  }
  return "?";
}

std::string domain_kind_names() {
  std::string names;
  for (DomainKind kind : kAllDomainKinds) names += (names.empty() ? "" : ", ") + std::string(to_string(kind));
  return names;
}

std::string Domain::describe(int dimension) const {
  switch (kind) {
    case DomainKind::torus: return fmt::format("the torus [{:g}, {:g})^{}", lo, lo + side, dimension);
    case DomainKind::cube: return fmt::format("the cube [{:g}, {:g}]^{}", lo, lo + side, dimension);
    case DomainKind::ball:
      return fmt::format("the {}D ball of radius {:g} centred at ({:g}, ..., {:g})", dimension, 0.5 * side, lo + 0.5 * side,
                         lo + 0.5 * side);
    case DomainKind::sphere:
      return lo == -1.0 && side == 2.0 ? fmt::format("the unit sphere S^{}", dimension - 1)
                                       : fmt::format("the sphere S^{} of radius {:g}", dimension - 1, 0.5 * side);
  }
  return "?";
}

}  // namespace dfvn
