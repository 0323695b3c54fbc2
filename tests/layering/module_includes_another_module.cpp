// Negative control (tests/layering/CMakeLists.txt): one system's cases never use another's. Built
// as a target that links voxref_timevarying_cases, this include must fail to compile.
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
