// Context factories of the two back ends (createContext in context.h dispatches to them).
#pragma once

#include <memory>

#include "gpu/context.h"

namespace voxref::gpu {

std::unique_ptr<Context> createOsmesaContext(Driver driver);  // llvmpipe or softpipe
void loadOsmesaLibrary();                                     // dlopen only: no context
std::unique_ptr<Context> createEglContext();                  // loads libEGL.so.1 at run time

}  // namespace voxref::gpu
