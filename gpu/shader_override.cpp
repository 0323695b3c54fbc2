#include "gpu/shader_override.h"

#include "gpu/shader_sources.h"

namespace voxref::gpu {

const std::vector<ShaderStage>& shaderStages() {
  const std::string_view vs = shaders::kFullscreenVert, lib = shaders::kSamplePointGlsl,
                         decoders = "Every decoder stage";
  static const std::vector<ShaderStage> stages = {
      {"combination", "combination.frag", shaders::kCombinationFrag, vs, lib, {}},
      {"timevarying_literal", "timevarying_literal.frag", shaders::kTimevaryingLiteralFrag, vs, lib, decoders},
      {"timevarying_paper", "timevarying_paper.frag", shaders::kTimevaryingPaperFrag, vs, lib, decoders},
      {"timevarying_texel_centre", "timevarying_texel_centre.frag", shaders::kTimevaryingTexelCentreFrag, vs, lib,
       decoders},
      {"timevarying_texel_fetch", "timevarying_texel_fetch.frag", shaders::kTimevaryingTexelFetchFrag, vs, lib,
       decoders},
  };
  return stages;
}

const ShaderStage* findShaderStage(std::string_view name) {
  for (const ShaderStage& s : shaderStages())
    if (s.name == name) return &s;
  return nullptr;
}

const ShaderStage& combinationStage() { return *findShaderStage("combination"); }

const ShaderStage& decoderStage(ref::DecoderVariant v) {
  return *findShaderStage("timevarying_" + std::string(ref::name(v)));
}

namespace {

// The text under the level-2 heading `heading` up to the next level-2 heading.
std::string_view section(std::string_view heading) {
  const std::string_view doc = shaders::kShaderInterfaceMd;
  const std::string start = "\n## " + std::string(heading) + "\n";
  const std::size_t at = doc.find(start);
  if (at == std::string_view::npos) return {};
  const std::size_t end = doc.find("\n## ", at + start.size());
  std::string_view text = doc.substr(at + 1, end == std::string_view::npos ? std::string_view::npos : end - at);
  while (!text.empty() && text.back() == '\n') text.remove_suffix(1);
  return text;
}

}  // namespace

std::string stageInterface(const ShaderStage& stage) {
  std::string text;
  if (!stage.family.empty()) text = std::string(section(stage.family)) + "\n\n";
  return text + std::string(section("Stage `" + std::string(stage.name) + "`"));
}

std::string_view commonInterface() { return section("Every stage"); }

Program buildStageProgram(Context& context, const ShaderStage& stage, const ShaderOverride* user) {
  const GlApi& gl = context.gl();
  const int glsl = context.info().glslNumber;
  if (!user || user->stage != stage.name)
    return Program(gl, glsl, stage.vertexSource, stage.fragmentSource, stage.fragmentFile, stage.library);
  ++user->programsBuilt;
  return Program(gl, glsl, stage.vertexSource, user->source, user->fileName, stage.library,
                 Program::Uniforms::Optional);
}

}  // namespace voxref::gpu
