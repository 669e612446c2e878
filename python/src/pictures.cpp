// Pictures and films (filled in with the renderer's in-memory output).
#include "common.hpp"

namespace dragon::python {

void bind_pictures(py::module_&) {}

}  // namespace dragon::python
