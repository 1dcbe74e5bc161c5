// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_NAMED_ENUMS_H
#define EXPMAP_PYTHON_NAMED_ENUMS_H

// The settings chosen by name as Python enums, made from the library's table
// (expmap/Option_names.h): members spelled with '_' where the command-line
// program has '-', and arguments that take a member or either spelling.

#include <expmap/Errors.h>
#include <expmap/Option_names.h>

#include <pybind11/pybind11.h>

#include <string>

namespace expmap_python {

namespace py = pybind11;

/// The Python enum `python_class` of `E`, a member per named value.
template <class E>
void bind_named_enum(py::module_& m, const char* python_class) {
  std::string doc = expmap::Option_names<E>::help;
  doc[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(doc[0])));
  py::enum_<E> e(m, python_class, (doc + ".").c_str());
  for (const expmap::Named_value<E>& v : expmap::Option_names<E>::values)
    e.value(expmap::python_name(v.name).c_str(), v.value, v.help);
}

/// The Python names of `E`'s values, quoted, for docstrings and messages.
template <class E>
std::string python_value_names() {
  std::string names;
  for (const expmap::Named_value<E>& v : expmap::Option_names<E>::values)
    names += (names.empty() ? "'" : ", '") + expmap::python_name(v.name) + "'";
  return names;
}

/// The docstring lines of the setting `keyword`: its class, its values
/// with their help (the default marked) and what it sets.
template <class E>
std::string enum_setting_doc(const char* keyword, const char* python_class, E default_value) {
  std::string doc = std::string(keyword) + ": a " + python_class + " or its name: " +
                    expmap::Option_names<E>::help + ".\n";
  for (const expmap::Named_value<E>& v : expmap::Option_names<E>::values)
    doc += "    '" + expmap::python_name(v.name) + "'" +
           (v.value == default_value ? " (default)" : "") + ": " + v.help + ".\n";
  return doc;
}

/// A setting given as a member of the bound enum `E` or by a name the
/// library accepts (Python's spelling or the command-line program's).
template <class E>
E enum_argument(py::handle value, const char* option) {
  if (py::isinstance<E>(value)) return value.cast<E>();
  if (py::isinstance<py::str>(value)) {
    try {
      return expmap::from_string<E>(value.cast<std::string>());
    } catch (const expmap::Invalid_input&) {
    }
  }
  throw expmap::Invalid_input(std::string(option) + " must be one of " + python_value_names<E>() +
                              " (got " + py::repr(value).cast<std::string>() + ")");
}

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_NAMED_ENUMS_H
