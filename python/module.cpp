// The Python module `dfvn`: the library's field, tracing, samplers and statistics on NumPy arrays.
// Names follow scipy.stats.qmc where it has one (n, seed, scramble, radius, ncandidates).
#include <pybind11/pybind11.h>

namespace dfvn::python {
void bind_field(pybind11::module_& module);
void bind_sampling(pybind11::module_& module);
void bind_stats(pybind11::module_& module);
}  // namespace dfvn::python

PYBIND11_MODULE(dfvn, module) {
  module.doc() =
      "Divergence-free vector noise (DFVN) in 2..8 dimensions, curl-noise jittering and point-set statistics\n"
      "(after 'Improving Curl Noise', SIGGRAPH Asia 2025). Point sets are (points, N) float64 arrays;\n"
      "results depend only on the inputs and the seed, never on the thread count.";
  module.attr("__version__") = DFVN_VERSION;
  dfvn::python::bind_field(module);
  dfvn::python::bind_sampling(module);
  dfvn::python::bind_stats(module);
}
