// Negative control (tests/layering/CMakeLists.txt): gpu/ never sees emulation/. Built as a target
// that links voxref_gpu, this include must fail to compile.
#include "emulation/profile.h"
