#include <filesystem>
#include <stdexcept>

#include "module.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/output_folder.h"

namespace saltus_python {

namespace {

PyObject* g_input_error = nullptr;
PyObject* g_output_error = nullptr;

/// An argument named as the CLI's flag ("--height") named as the module's keyword ("height").
std::string as_keyword(const std::string& name) {
  if (name.rfind("--", 0) != 0 || name.size() < 3) return name;
  std::string keyword = name.substr(2);
  for (char& c : keyword)
    if (c == '-') c = '_';
  return keyword;
}

/// Raises `type` with `message` and the attributes `file`, `field` and `problem`.
void raise_with_fields(PyObject* type, const std::string& message, const std::string& file,
                       const std::string& field, const std::string& problem) {
  py::object error = py::reinterpret_borrow<py::object>(type)(message);
  error.attr("file") = file;
  error.attr("field") = field;
  error.attr("problem") = problem;
  PyErr_SetObject(type, error.ptr());
}

}  // namespace

[[noreturn]] void throw_input_error(const std::string& field, const std::string& problem) {
  throw saltus::InputError(field, "", problem);
}

void bind_errors(py::module_& m) {
  g_input_error = PyErr_NewExceptionWithDoc(
      "saltus.InputError",
      "Bad input: a file, a field of it or an argument the library refuses. The message names "
      "the file and the field as the CLI's does (the CLI ends with status 2); `file`, `field` "
      "(a JSON path, or '') and `problem` hold its parts. A ValueError.",
      PyExc_ValueError, nullptr);
  g_output_error = PyErr_NewExceptionWithDoc(
      "saltus.OutputError",
      "A result could not be written (another run is writing the same folder, or the system "
      "refused: disk full, no permission); nothing was changed (the CLI ends with status 4). An "
      "OSError.",
      PyExc_OSError, nullptr);
  m.add_object("InputError", py::reinterpret_borrow<py::object>(g_input_error));
  m.add_object("OutputError", py::reinterpret_borrow<py::object>(g_output_error));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const saltus::InputError& e) {
      const std::string file = as_keyword(e.file());
      if (file == e.file())
        raise_with_fields(g_input_error, e.what(), e.file(), e.json_path(), e.problem());
      else
        raise_with_fields(g_input_error,
                          saltus::InputError(file, e.json_path(), e.problem()).what(), file,
                          e.json_path(), e.problem());
    } catch (const saltus::OutputError& e) {
      raise_with_fields(g_output_error, e.what(), "", "", e.what());
    } catch (const saltus::OptionValueError& e) {
      raise_with_fields(g_input_error, e.what(), "", "", e.problem());
    } catch (const std::invalid_argument& e) {
      // What the CLI reports as bad input too (exit status 2): a value the library refuses.
      raise_with_fields(g_input_error, e.what(), "", "", e.what());
    } catch (const std::filesystem::filesystem_error& e) {
      raise_with_fields(g_input_error, e.what(), e.path1().string(), "", e.code().message());
    }
  });
}

}  // namespace saltus_python
