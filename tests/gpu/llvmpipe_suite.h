// Test helper: a test suite that shares one llvmpipe context among its tests (made before the
// suite's first test, deleted after its last), for the GL layer's tests of label `gl`. A suite
// derives from it: class GlObjects : public LlvmpipeSuite {};
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "gpu/context.h"

namespace voxref::gpu {

class LlvmpipeSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = createContext(Driver::Llvmpipe); }
  static void TearDownTestSuite() { context_.reset(); }
  static inline std::unique_ptr<Context> context_;
};

}  // namespace voxref::gpu
