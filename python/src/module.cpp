// The Python module `saltus` (python/README.md): the library's use cases as Python functions,
// their results as objects with numpy arrays. Each file binds one part (module.h).

#include "module.h"
#include "saltus/optim/solver_memory.h"

PYBIND11_MODULE(saltus, m) {
  namespace sp = saltus_python;
  // Every docstring begins with its own signature line, which Python reads (inspect.signature,
  // help()): optimize's lists the option table's keywords, generated from the table.
  pybind11::options options;
  options.disable_function_signatures();
  m.doc() =
      "Saltus: physics-based simulation of human aerial motion (somersaults, dives, twists).\n\n"
      "The library's verbs as functions: read_motion, read_model, evaluate, simulate, optimize, "
      "analyse_twist, what_if, import_capture, export, model_new, model_yeadon, model_scale, "
      "model_info and the studies; results carry numpy arrays (SI units, degrees where named) "
      "and write the CLI's result folders. Bad input raises InputError (a ValueError) naming the "
      "file and field. docs/python.md.";
  m.attr("__version__") = "0.1.0";
  // The process-wide setting the `saltus` program makes in its main (optim/solver_memory.h):
  // without it every solver iteration maps its fronts afresh, and optimize from Python would be
  // slower than the CLI.
  saltus::keep_solver_memory_in_heap();
  sp::bind_errors(m);
  sp::bind_options(m);
  sp::bind_motions(m);
  sp::bind_flights(m);
  sp::bind_runs(m);
  sp::bind_analyses(m);
  sp::bind_verbs(m);
}
