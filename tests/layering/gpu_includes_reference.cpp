// Positive control (tests/layering/CMakeLists.txt): what a layer may use compiles in the same set-up,
// so the negative controls fail for their include alone.
#include "gpu/context.h"
#include "reference/common/volume.h"
