// dfvn._core, the compiled part of the Python package `dfvn` (python/dfvn/): the library's field,
// tracing, samplers and statistics on NumPy arrays.
// Names follow scipy.stats.qmc where it has one (n, seed, scramble, radius, ncandidates).
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "dfvn/core/bulk_memory.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/io/csv.hpp"

namespace dfvn::python {

// The library's messages name the command line's options ("--grid 4", "-n 1000"); here each becomes
// the keyword argument that sets the same value, so that a Python caller is never told about an
// option it cannot give ("--grid 4" becomes "grid=4"). An option is replaced where it stands as a
// word: after the start, a space, '(' or a quote, and before a character that cannot continue its name.
std::string python_message(std::string message) {
  static const std::pair<std::string_view, std::string_view> kKeywords[] = {
      {"--dim", "dim"},           {"--grid", "grid"},           {"-n", "n"},
      {"--seed", "seed"},         {"--threads", "threads"},     {"--methods", "method"},
      {"--frequency", "frequency"}, {"--cycles-per-spacing", "cycles_per_spacing"}, {"--step-scale", "step_scale"}, {"--steps", "steps"},
      {"--noise", "noise"},       {"--integrator", "integrator"}, {"--reproject", "reprojection"}, {"--field", "field"},
      {"--protocol", "protocol"}, {"--scramble", "scramble"},   {"--pds-radius", "radius"},
      {"--pds-candidates", "ncandidates"}, {"--max-memory GIB", "max_memory_gib"},
      {"--max-memory", "max_memory_gib"}, {"--domain-side", "domain_side"}, {"--rdf-max", "r_max"},
      {"--rdf-bins", "bins"},     {"--rdf-queries", "max_queries"}, {"--knn", "knn"},
      {"--phase", "phase"},       {"--time", "time"},           {"--stretch", "stretch"},
      {"--lift-ramp", "lift_ramp"}, {"--lift", "lift"},         {"--obstacle", "obstacles"},
      {"--steer-dir", "steer"},   {"--steer-field", "steer"},   {"--steer-k", "steer_k"},
      {"--boundary-width", "boundary_width"}, {"--domain-mode", "domain_mode"}, {"--domain", "domain"},
      {"--bound", "bound"}};
  // Library messages that name a value in words where the command line's validator named the option.
  static const std::pair<std::string_view, std::string_view> kPhrases[] = {
      {"the boundary's transition width must be", "boundary_width (the boundary's transition width) must be"},
      {"thread count must be", "threads must be"},
      {"step scale must be", "step_scale must be"},
      {"CNJ steps must be", "steps must be"},
      {"obstacle 'sphere", "obstacles: 'sphere"},
      {"obstacle sphere", "obstacles: sphere"},
      {"unknown KD-tree backend", "knn: unknown KD-tree backend"},
      {"unknown discrepancy", "method: unknown discrepancy"}};
  for (const auto& [phrase, replacement] : kPhrases)
    if (const std::size_t at = message.find(phrase); at != std::string::npos) message.replace(at, phrase.size(), replacement);
  // "point 3, column 2: ..." and "point 0 (0-based) has ...": a row of the argument `points`.
  if (message.starts_with("point ")) message = "points: " + message;
  auto continues_name = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_'; };
  for (const auto& [option, keyword] : kKeywords) {
    for (std::size_t at = message.find(option); at != std::string::npos; at = message.find(option, at)) {
      const bool starts = at == 0 || message[at - 1] == ' ' || message[at - 1] == '(' || message[at - 1] == '\'';
      const std::size_t end = at + option.size();
      if (starts && (end == message.size() || !continues_name(message[end]))) {
        // "--grid 4" reads "grid=4", as the call would write it.
        const bool valued = end + 1 < message.size() && message[end] == ' ' &&
                            std::string_view("0123456789-.'").find(message[end + 1]) != std::string_view::npos;
        const std::string replacement = std::string(keyword) + (valued ? "=" : "");
        message.replace(at, option.size() + (valued ? 1 : 0), replacement);
        at += replacement.size();
      } else {
        at += option.size();
      }
    }
  }
  return message;
}

void bind_field(pybind11::module_& module);
void bind_sampling(pybind11::module_& module);
void bind_stats(pybind11::module_& module);
void bind_sequence(pybind11::module_& module);
}  // namespace dfvn::python

PYBIND11_MODULE(_core, module) {
  module.doc() =
      "Divergence-free vector noise (DFVN) in 2..8 dimensions, curl-noise jittering and point-set statistics\n"
      "(after 'Improving Curl Noise', SIGGRAPH Asia 2025). Point sets are (points, N) float64 arrays;\n"
      "results depend only on the inputs and the seed, never on the thread count.";
  module.attr("__version__") = DFVN_VERSION;
  // Every function takes or returns NumPy arrays: import NumPy with the module, so that its import
  // (about 70 ms here) is not charged to the first call.
  pybind11::module_::import("numpy");
  // Bad values raise ValueError with the library's message, in the keywords' names, on one line (control
  // bytes of echoed values escaped, as the command line's fail() does); memory that cannot be had raises
  // MemoryError saying how much (core/bulk_memory.hpp's OutOfMemory), never the allocator's own words.
  pybind11::register_exception_translator([](std::exception_ptr thrown) {
    const auto raise = [](PyObject* type, const std::string& message) {
      PyErr_SetString(type, dfvn::escape_bytes(dfvn::python::python_message(message), false).c_str());
    };
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const std::invalid_argument& e) {
      raise(PyExc_ValueError, e.what());
    } catch (const dfvn::InputError& e) {
      raise(PyExc_ValueError, e.what());
    } catch (const dfvn::OutOfMemory& e) {
      raise(PyExc_MemoryError, e.what());
    } catch (const std::bad_alloc&) {
      raise(PyExc_MemoryError, "out of memory: try a smaller problem");
    } catch (const std::length_error&) {  // a std::vector longer than its max_size()
      raise(PyExc_MemoryError, "out of memory: more elements than an array can hold; try a smaller problem");
    } catch (const pybind11::builtin_exception& e) {  // the bindings' own ValueError and TypeError
      e.set_error();
      PyObject *type = nullptr, *value = nullptr, *traceback = nullptr;
      PyErr_Fetch(&type, &value, &traceback);
      PyErr_SetString(type, dfvn::escape_bytes(e.what(), false).c_str());
      Py_XDECREF(type);
      Py_XDECREF(value);
      Py_XDECREF(traceback);
    }
  });
  dfvn::python::bind_field(module);
  dfvn::python::bind_sampling(module);
  dfvn::python::bind_stats(module);
  dfvn::python::bind_sequence(module);
}
