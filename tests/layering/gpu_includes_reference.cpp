// Positive control (tests/layering/CMakeLists.txt): what a layer may use compiles in the same set-up,
// so the negative controls fail for their include alone.
#include "reference/common/volume.h"
#include "gpu/context.h"
