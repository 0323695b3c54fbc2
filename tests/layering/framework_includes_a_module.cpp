// Negative control (tests/layering/CMakeLists.txt): the harness knows no system. Built as a target
// that links voxref_framework, this include must fail to compile.
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
