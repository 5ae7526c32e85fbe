#include <climits>
#include <cmath>

#include "module.h"

namespace saltus_python {

namespace {

using saltus::OptionKind;
using saltus::OptionSpec;
using saltus::OptionUse;
using saltus::OptionValue;

bool offered(const OptionSpec& spec, OptionUse runs) {
  return runs == OptionUse::kOptimization || spec.use == OptionUse::kEvaluation;
}

/// A default as Python writes it in a signature: 'relaxed', 300, 1e-08, 0.25, False.
std::string python_literal(const OptionSpec& spec, const OptionValue& value) {
  if (spec.kind == OptionKind::kSwitch) return "False";  // the flag is not given
  if (const auto* s = std::get_if<std::string>(&value)) return "'" + *s + "'";
  std::string text = saltus::option_value_text(value);
  if (std::holds_alternative<double>(value) && text.find_first_of(".e") == std::string::npos)
    text += ".0";
  return text;
}

std::string python_type(const OptionSpec& spec, OptionUse runs) {
  switch (spec.kind) {
    case OptionKind::kSwitch:
      return "bool";
    case OptionKind::kChoice:
      return "str";
    case OptionKind::kInteger:
      return spec.takes_word(runs) ? "int or '" + spec.word + "'" : "int";
    case OptionKind::kReal:
      return spec.takes_word(runs) ? "float or '" + spec.word + "'" : "float";
  }
  return "";
}

/// The table's words for people with each flag written as its keyword ("--formulation strict"
/// -> "formulation strict").
std::string with_keywords(std::string text) {
  for (const OptionSpec& other : saltus::option_table()) {
    const std::string keyword = option_keyword(other);
    for (std::size_t at = text.find(other.flag); at != std::string::npos;
         at = text.find(other.flag, at + keyword.size())) {
      const std::size_t end = at + other.flag.size();
      const bool whole = end == text.size() ||
                         !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-');
      if (whole)
        text.replace(at, other.flag.size(), keyword);
      else
        at += 1;
    }
  }
  return text;
}

/// A keyword argument's value as the table's: bool, int, float or str as given (numpy scalars
/// too); the table's own check decides whether it fits the option.
OptionValue table_value(const OptionSpec& spec, py::handle value, const std::string& keyword,
                        OptionUse runs) {
  const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
  const bool is_bool = py::isinstance<py::bool_>(value) || py::isinstance(value, numpy_bool);
  if (spec.kind == OptionKind::kSwitch) {
    if (!is_bool) throw_input_error(keyword, "expected True or False");
    // The keyword is the flag: True turns the option away from its default, as the flag does.
    const bool flagged = PyObject_IsTrue(value.ptr()) == 1;
    return flagged != std::get<bool>(spec.default_value(runs));
  }
  if (is_bool) return PyObject_IsTrue(value.ptr()) == 1;
  if (py::isinstance<py::str>(value)) return py::cast<std::string>(value);
  if (!PyFloat_Check(value.ptr()) && PyIndex_Check(value.ptr())) {
    const py::int_ whole = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(whole.ptr(), &overflow);
    if (overflow != 0 || v > INT_MAX || v < INT_MIN)
      throw_input_error(
          keyword, py::cast<std::string>(py::repr(whole)) +
                       " is out of range (allowed: " + saltus::option_range_text(spec, runs) + ")");
    return static_cast<int>(v);
  }
  if (PyFloat_Check(value.ptr()) || py::hasattr(value, "__float__")) {
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
    return v;
  }
  throw_input_error(keyword, "expected " + python_type(spec, runs) +
                                 " (allowed: " + saltus::option_range_text(spec, runs) + "), got " +
                                 std::string(py::str(value.get_type().attr("__name__"))));
}

}  // namespace

std::string option_keyword(const OptionSpec& spec) {
  std::string keyword = spec.flag.substr(spec.flag.find_first_not_of('-'));
  for (char& c : keyword)
    if (c == '-') c = '_';
  return keyword;
}

saltus::OptionValues option_values(const py::kwargs& kwargs, OptionUse runs, const char* function) {
  saltus::OptionValues values(runs);
  for (const auto& [key, value] : kwargs) {
    const std::string keyword = py::cast<std::string>(key);
    const OptionSpec* found = nullptr;
    for (const OptionSpec& spec : saltus::option_table())
      if (offered(spec, runs) && option_keyword(spec) == keyword) found = &spec;
    if (!found)
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                           keyword + "'");
    const OptionValue v = table_value(*found, value, keyword, runs);
    try {
      values.set(found->name, v);
    } catch (const saltus::OptionValueError& e) {
      throw_input_error(keyword, with_keywords(e.problem()));
    }
  }
  return values;
}

std::string option_parameters(OptionUse runs) {
  std::string out;
  for (const OptionSpec& spec : saltus::option_table())
    if (offered(spec, runs))
      out += (out.empty() ? "" : ", ") + option_keyword(spec) + "=" +
             python_literal(spec, spec.default_value(runs));
  return out;
}

std::string option_docs(OptionUse runs) {
  std::string out;
  for (const OptionSpec& spec : saltus::option_table()) {
    if (!offered(spec, runs)) continue;
    out += option_keyword(spec) + " : " + python_type(spec, runs) + ", default " +
           python_literal(spec, spec.default_value(runs)) + "\n    " +
           with_keywords(saltus::option_description(spec, runs)) + " (CLI: " + spec.flag + ")\n";
  }
  return out;
}

std::string documented(const std::string& signature, const std::string& text) {
  return signature + "\n--\n\n" + text;
}

void bind_options(py::module_& m) {
  m.def(
      "option_table",
      []() {
        py::list out;
        for (const OptionSpec& spec : saltus::option_table()) {
          py::dict d;
          d["keyword"] = option_keyword(spec);
          d["flag"] = spec.flag;
          d["name"] = spec.name;
          d["label"] = spec.label;
          d["unit"] = spec.unit;
          d["type"] = python_type(spec, OptionUse::kOptimization);
          d["default"] = python_json(saltus::option_value_json(
              spec.kind == OptionKind::kSwitch ? OptionValue(false)
                                               : spec.default_value(OptionUse::kOptimization)));
          d["evaluation_default"] = spec.use == OptionUse::kEvaluation
                                        ? python_json(saltus::option_value_json(
                                              spec.default_value(OptionUse::kEvaluation)))
                                        : py::object(py::none());
          d["allowed"] = saltus::option_range_text(spec, OptionUse::kOptimization);
          d["description"] = with_keywords(saltus::option_description(spec));
          d["evaluation"] = spec.use == OptionUse::kEvaluation;
          out.append(d);
        }
        return out;
      },
      documented("option_table()",
                 "Every option of the library's option table, in its order, as a list of dicts: "
                 "the keyword `optimize` takes (`evaluate`, `simulate` and the analyses take "
                 "those with `evaluation` True), the CLI's flag, the unit, the type, the default "
                 "(`evaluation_default`: of evaluate and simulate), the allowed values and what "
                 "it does. A switch's keyword is its flag, so its default is False.")
          .c_str());
}

}  // namespace saltus_python
