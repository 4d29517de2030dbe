// def_checked(module, name, f, extra...): module.def(name, f, extra...), except that an argument pybind11
// cannot convert raises one line naming it, e.g. "field(): seed must be an integer in [0, 2^64), got -1",
// instead of pybind11's multi-line "incompatible function arguments" listing of every signature. The
// function is pybind11's own, called as it is; only when pybind11 refuses the call are the arguments
// converted again one by one, each with its parameter's caster, to find which one it was (TypeError for a
// value of another kind, ValueError for an integer or a real that its type cannot hold). Its docstring,
// first line (the signature) included, is the function's.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "dfvn/core/message_text.hpp"

namespace dfvn::python {

namespace py = pybind11;

namespace checked {

// What a parameter of C++ type T takes, for the message, and whether it is a number: an integer (a Python
// int it cannot hold is a ValueError) or a real (an int or float it cannot hold, 10**400, is one).
enum class Number { no, integer, real };
template <typename T>
struct Expected {
  static std::string text() { return std::string("a value of type ") + py::detail::make_caster<T>::name.text; }
  static constexpr Number number = Number::no;
};
template <>
struct Expected<bool> {
  static std::string text() { return "True or False"; }
  static constexpr Number number = Number::no;
};
template <>
struct Expected<int> {
  static std::string text() { return "an integer in [-2^31, 2^31)"; }
  static constexpr Number number = Number::integer;
};
template <>
struct Expected<long> {
  static std::string text() { return "an integer in [-2^63, 2^63)"; }
  static constexpr Number number = Number::integer;
};
template <>
struct Expected<unsigned long> {
  static std::string text() { return "an integer in [0, 2^64)"; }
  static constexpr Number number = Number::integer;
};
template <>
struct Expected<double> {
  static std::string text() { return "a real number"; }
  static constexpr Number number = Number::real;
};
template <>
struct Expected<std::string> {
  static std::string text() { return "a str"; }
  static constexpr Number number = Number::no;
};
template <typename T>
struct Expected<std::optional<T>> {
  static std::string text() { return "None or " + Expected<T>::text(); }
  static constexpr Number number = Expected<T>::number;
};
template <>
struct Expected<std::vector<std::string>> {
  static std::string text() { return "a list of str"; }
  static constexpr Number number = Number::no;
};
template <>
struct Expected<std::vector<double>> {
  static std::string text() { return "a sequence of real numbers"; }
  static constexpr Number number = Number::no;
};
template <typename T, int Flags>
struct Expected<py::array_t<T, Flags>> {
  static std::string text() { return "an array of numbers"; }
  static constexpr Number number = Number::no;
};

// The value as the message shows it: its repr, shortened and escaped, and its type.
inline std::string shown(py::handle value) {
  std::string repr;
  try {
    repr = py::repr(value).cast<std::string>();
  } catch (const py::error_already_set&) {
    repr = "?";
  }
  constexpr std::size_t kChars = 40;
  if (repr.size() > kChars) repr = repr.substr(0, kChars) + "...";
  return escape_bytes(repr, false) + " (" + py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>() + ")";
}

// What def_checked knows of the parameters from the py::arg annotations, in order.
struct Parameters {
  std::vector<std::string> names;
  std::vector<bool> has_default;
  std::size_t positional = static_cast<std::size_t>(-1);  // how many may be given by position (py::kw_only)
};
inline void collect(Parameters& p, const py::arg_v& a) {
  p.names.emplace_back(a.name ? a.name : "");
  p.has_default.push_back(true);
}
inline void collect(Parameters& p, const py::arg& a) {
  p.names.emplace_back(a.name ? a.name : "");
  p.has_default.push_back(false);
}
inline void collect(Parameters& p, const py::kw_only&) { p.positional = p.names.size(); }
template <typename Other>
void collect(Parameters&, const Other&) {}

template <typename Signature>
struct Arguments;
template <typename Return, typename... Args>
struct Arguments<Return(Args...)> {
  using Types = std::tuple<std::decay_t<Args>...>;
  static constexpr std::size_t count = sizeof...(Args);
};

// Throws the one-line error for argument I if its caster refuses it.
template <typename T>
void check_argument(const std::string& function, const std::string& name, py::handle value) {
  py::detail::make_caster<T> caster;
  bool loaded = false;
  try {
    loaded = caster.load(value, true);
  } catch (const py::error_already_set&) {
    loaded = false;
  }
  PyErr_Clear();
  if (loaded) return;
  const bool is_int = PyLong_Check(value.ptr()) && !PyBool_Check(value.ptr());
  const bool is_real = is_int || PyFloat_Check(value.ptr());
  const std::string message = function + "(): " + name + " must be " + Expected<T>::text() + ", got " + shown(value);
  // A number of the right kind that the type cannot hold (2**64 for a seed, 10**400 for a real) is a value error.
  constexpr Number number = Expected<T>::number;
  if ((number == Number::integer && is_int) || (number == Number::real && is_real)) throw py::value_error(message);
  throw py::type_error(message);
}

template <typename Types, std::size_t... I>
void diagnose(const std::string& function, const Parameters& p, const py::args& args, const py::kwargs& kwargs,
              std::index_sequence<I...>) {
  if (args.size() > std::min(p.positional, p.names.size()))
    throw py::type_error(function + "() takes " + std::to_string(std::min(p.positional, p.names.size())) +
                         " positional arguments but " + std::to_string(args.size()) + " were given");
  for (const auto& item : kwargs) {
    const std::string key = py::str(item.first).cast<std::string>();
    bool known = false;
    for (std::size_t i = 0; i < p.names.size(); ++i) known = known || (p.names[i] == key && (i >= args.size()));
    if (!known)
      throw py::type_error(function + "() got an unexpected keyword argument " + quote_for_message(key) +
                           " (or gave it twice)");
  }
  const auto check = [&](auto index, auto type) {
    using T = typename decltype(type)::type;
    constexpr std::size_t i = decltype(index)::value;
    if (i >= p.names.size()) return;
    if (i < args.size()) {
      check_argument<T>(function, p.names[i], args[i]);
    } else if (kwargs.contains(p.names[i].c_str())) {
      check_argument<T>(function, p.names[i], kwargs[p.names[i].c_str()]);
    } else if (!p.has_default[i]) {
      throw py::type_error(function + "() is missing its argument " + quote_for_message(p.names[i]));
    }
  };
  (check(std::integral_constant<std::size_t, I>{}, std::type_identity<std::tuple_element_t<I, Types>>{}), ...);
}

}  // namespace checked

template <typename Function, typename... Extra>
void def_checked(py::module_& module, const char* name, Function&& f, const Extra&... extra) {
  using Signature = py::detail::function_signature_t<std::remove_reference_t<Function>>;
  using A = checked::Arguments<Signature>;
  checked::Parameters parameters;
  (checked::collect(parameters, extra), ...);
  module.def(name, std::forward<Function>(f), extra...);
  py::object original = module.attr(name);
  // The docstrings live as long as the module (pybind11 keeps the pointer).
  static std::deque<std::string> docs;
  docs.push_back(py::str(original.attr("__doc__")).cast<std::string>());
  const std::string function = name;
  py::options options;
  options.disable_function_signatures();  // the docstring is the original's, its signature line included
  module.attr(name) = py::cpp_function(
      [original, parameters, function](const py::args& args, const py::kwargs& kwargs) -> py::object {
        try {
          return original(*args, **kwargs);
        } catch (py::error_already_set& e) {
          if (!e.matches(PyExc_TypeError) ||
              py::str(e.value()).cast<std::string>().find("incompatible function arguments") == std::string::npos)
            throw;
          checked::diagnose<typename A::Types>(function, parameters, args, kwargs, std::make_index_sequence<A::count>{});
          throw;
        }
      },
      py::name(name), py::scope(module), py::doc(docs.back().c_str()));
}

}  // namespace dfvn::python
