// Tests of user shaders in place of built-in stages (label `gl`): the stage table matches the
// built-in shaders and docs/shader-interface.md, errors carry the user's line numbers, and an
// override reaches only the stage it names.
#include "gpu/shader_override.h"

#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu/llvmpipe_suite.h"

#include "gpu/gl_error.h"

namespace voxref::gpu {
namespace {

class ShaderOverrides : public LlvmpipeSuite {};

TEST(ShaderStages, EveryUniformOfEveryBuiltInShaderIsDocumented) {
  ASSERT_FALSE(commonInterface().empty());
  EXPECT_NE(commonInterface().find("samplePoint()"), std::string_view::npos);
  const std::regex uniform(R"(uniform\s+\w+\s+(\w+)\s*;)");
  for (const ShaderStage& stage : shaderStages()) {
    const std::string doc(stageInterface(stage));
    ASSERT_FALSE(doc.empty()) << stage.name << " has no section in docs/shader-interface.md";
    const std::string source(stage.fragmentSource);
    for (auto it = std::sregex_iterator(source.begin(), source.end(), uniform); it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[1];
      EXPECT_NE(doc.find(name), std::string::npos) << stage.name << ": uniform " << name << " is not in its section";
    }
  }
}

TEST(ShaderStages, DecoderStagesAreNamedAfterTheirVariants) {
  EXPECT_EQ(decoderStage(ref::DecoderVariant::TexelCentre).fragmentFile, "timevarying_texel_centre.frag");
  EXPECT_EQ(combinationStage().name, "combination");
  EXPECT_EQ(findShaderStage("iso_mesh"), nullptr);
}

TEST_F(ShaderOverrides, CompileErrorsAreReportedAtTheUsersLine) {
  const ShaderOverride user{"combination",
                            "out vec4 c;\n\nvoid main() {\n  vec3 p = samplePoint();\n  c = vec4(p * nope, 1.0);\n}\n",
                            "mine.frag"};
  try {
    (void)buildStageProgram(*context_, combinationStage(), &user);
    FAIL() << "compiled";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("mine.frag (fragment) failed to compile"), std::string::npos) << e.what();
    EXPECT_NE(e.infoLog().find("0:5("), std::string::npos)
        << e.infoLog();  // line 5 of the file, after prelude and library
  }
  EXPECT_EQ(user.programsBuilt, 1);
}

TEST_F(ShaderOverrides, AnOverrideReachesOnlyItsStageAndMayLeaveUniformsOut) {
  const ShaderOverride user{"timevarying_paper", "out vec4 c;\nvoid main() { c = vec4(samplePoint(), 1.0); }\n",
                            "mine.frag"};
  const Program builtIn = buildStageProgram(*context_, combinationStage(), &user);
  EXPECT_EQ(user.programsBuilt, 0);
  EXPECT_THROW(builtIn.uniform("noSuchUniform"), GlError);
  const Program mine = buildStageProgram(*context_, decoderStage(ref::DecoderVariant::Paper), &user);
  EXPECT_EQ(user.programsBuilt, 1);
  EXPECT_EQ(mine.uniform("slotScale"), -1);  // not declared: not set, no error
  EXPECT_GE(mine.uniform("planeOrigin"), 0);
}

}  // namespace
}  // namespace voxref::gpu
