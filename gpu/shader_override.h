// A user's GLSL in place of a built-in fragment shader (`voxref check-shader`,
// docs/shader-interface.md). A stage is the fragment shader of one GL pass, named by the stem of
// its built-in file ("combination", "timevarying_paper", ...). An override travels as data from the
// command line through conf::CaseContext to the pass, which compiles it instead of the built-in
// shader with the same prelude, library, vertex shader, uniforms, textures and GL state.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gpu/context.h"
#include "gpu/gl_objects.h"
#include "reference/timevarying/decoder_variants.h"

namespace voxref::gpu {

struct ShaderOverride {
  std::string stage;     // the ShaderStage whose fragment shader `source` replaces
  std::string source;    // the user's GLSL, without #version (Program's prelude adds it)
  std::string fileName;  // named in compile errors and reports
  // Programs built from `source` so far. The passes count them, so that a caller can tell a case
  // that ran the override from one that never reached the stage (GL skipped, another stage).
  mutable int programsBuilt = 0;
};

// One replaceable stage and what its pass compiles around the fragment shader.
struct ShaderStage {
  std::string_view name;            // "combination"
  std::string_view fragmentFile;    // "combination.frag"
  std::string_view fragmentSource;  // the built-in shader
  std::string_view vertexSource;    // the pass's vertex shader (not replaceable)
  std::string_view library;         // inserted between the prelude and the fragment shader (may be empty)
  std::string_view family;          // heading of the interface section it shares with sibling stages (may be empty)
};

// Every replaceable stage, in a fixed order: combination, then the decoder variants.
const std::vector<ShaderStage>& shaderStages();
// The stage named `name`, or nullptr.
const ShaderStage* findShaderStage(std::string_view name);
const ShaderStage& combinationStage();                   // combination_gl.h
const ShaderStage& decoderStage(ref::DecoderVariant v);  // timevarying_gl.h

// The stage's interface from docs/shader-interface.md (uniforms, samplers, inputs, outputs): its
// family's section, then its own; empty when the document has neither. commonInterface(): the
// section that holds for every stage (prelude, library).
std::string stageInterface(const ShaderStage& stage);
std::string_view commonInterface();

// The program of `stage`: from the user's source when `user` replaces this stage (counted in
// user->programsBuilt; uniforms the user's shader does not read are tolerated, Program::Uniforms),
// else from the built-in source. Throws ShaderError carrying the driver's info log, whose line
// numbers are those of the user's file, when it does not compile or link.
Program buildStageProgram(Context& context, const ShaderStage& stage, const ShaderOverride* user);

}  // namespace voxref::gpu
