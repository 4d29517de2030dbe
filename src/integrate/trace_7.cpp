#include "dfvn/integrate/trace_impl.hpp"

namespace dfvn {
DFVN_INSTANTIATE_TRACER(7)
}  // namespace dfvn
