#include "dfvn/integrate/trace_impl.hpp"

namespace dfvn {
DFVN_INSTANTIATE_TRACER(6)
}  // namespace dfvn
