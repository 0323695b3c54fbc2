// voxref encode | decode | info --codec NAME: the codecs on the user's own volumes.
#include "conformance/cli/codecs.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"

namespace voxref::cli {
namespace {

enum class Codec { TimeVarying, Leb };

Codec codecOf(const std::string& name) {
  if (name == "timevarying") return Codec::TimeVarying;
  if (name == "leb") return Codec::Leb;
  throw conf::UsageError("unknown codec '" + name + "' (known: timevarying, leb)");
}

int runEncode(const EncodeOptions& o) {
  return codecOf(o.codec) == Codec::Leb ? encodeLebCommand(o) : encodeTimeVaryingCommand(o);
}
int runDecode(const DecodeOptions& o) {
  return codecOf(o.codec) == Codec::Leb ? decodeLebCommand(o) : decodeTimeVaryingCommand(o);
}
int runInfo(const InfoOptions& o) {
  return codecOf(o.codec) == Codec::Leb ? infoLebCommand(o) : infoTimeVaryingCommand(o);
}

}  // namespace

std::vector<Subcommand> addCodecCommands(CLI::App& app) {
  auto encode = std::make_shared<EncodeOptions>();
  auto decode = std::make_shared<DecodeOptions>();
  auto info = std::make_shared<InfoOptions>();
  CLI::App* encodeCmd = app.add_subcommand("encode", "encode volumes with a codec into a file");
  encodeCmd->add_option("--codec", encode->codec, "timevarying or leb")->required();
  encodeCmd->add_option("--input", encode->inputs,
                        "raw volume files (.raw or .raw.gz): timevarying one per time step, leb one");
  encodeCmd->add_option("--dims", encode->dims, "X Y Z extents of every input volume")->expected(3);
  encodeCmd->add_option("--type", encode->type, "voxel type of the inputs: uint8, or uint16 (leb; little endian)")
      ->default_val("uint8");
  encodeCmd->add_flag("--plume", encode->plume, "encode the synthetic discharge plume instead of files");
  encodeCmd->add_option("--sparseness", encode->sparseness, "plume: fraction of zero voxels to aim for (e.g. 0.9965)");
  encodeCmd->add_option("--side", encode->plumeSide, "plume: volume side (power of two)")->default_val(128);
  encodeCmd->add_option("--steps", encode->plumeSteps, "plume: time steps")->default_val(36);
  encodeCmd->add_option("--tf", encode->transfer, "transfer function: plume, opaque, gray")->default_val("plume");
  encodeCmd->add_option("--level", encode->level, "subdivision level, or auto (the level whose file is smallest)")
      ->default_val("auto");
  encodeCmd
      ->add_option("--encoding", encode->encoding,
                   "index encoding: normalized_rgba8 (paper), normalized_rgba16, normalized_float, block_rgba8")
      ->default_val("normalized_rgba8");
  encodeCmd
      ->add_option("--alpha-one", encode->alphaOne, "homogeneous colours with alpha 255: refine (lossless) or paper")
      ->default_val("refine");
  encodeCmd->add_option("--page-bits", encode->pageBits, "leb: pages of 2^N points (4..20)")->default_val(12);
  encodeCmd
      ->add_option("--coder", encode->lebCoder,
                   "leb: the pages' entropy stage: lead1 (the paper's Huffman code; a version 2 stream), adaptive "
                   "(voxref's range coder; version 3) or context (voxref's range coder of the samples from their "
                   "corners, and of the gradients from theirs and the unit sphere; version 4)")
      ->default_val("lead1");
  encodeCmd->add_flag("--no-gradients", encode->noGradients, "leb: code the data only, no gradients channel");
  encodeCmd->add_flag("--derive-gradients", encode->deriveGradients,
                      "leb: store no gradients channel; the decoder derives the gradients from the samples (the same "
                      "bytes: reference/leb/FORMAT.md, header byte 23)");
  encodeCmd
      ->add_option("--mirror", encode->mirror,
                   "leb: off, or auto: find the planes the volume is its own mirror image across and store one side "
                   "of each (a mirrored stream, reference/leb/FORMAT.md \"Mirrored streams\"; stored gradients "
                   "fold with it, a component negated across its plane)")
      ->default_val("off");
  encodeCmd->add_option("--bounds-out", encode->boundsOut,
                        "leb: also write the per-diamond min, max and error for isosurfaces (.vxlbb)");
  encodeCmd->add_option("--out", encode->out, "output file (.vxtv, .vxleb)")->required();

  CLI::App* decodeCmd = app.add_subcommand("decode", "decode a codec file into raw volumes");
  decodeCmd->add_option("--codec", decode->codec, "timevarying or leb")->required();
  decodeCmd->add_option("--input", decode->input, "file to decode")->required();
  decodeCmd
      ->add_option("--out", decode->out,
                   "timevarying: output directory (step_NNN.rgba: RGBA8 voxels, x fastest); leb: the raw volume file")
      ->required();
  decodeCmd->add_option("--step", decode->step, "timevarying: only this time step (0-based; default: every step)");
  decodeCmd->add_option("--gradients-out", decode->gradientsOut,
                        "leb: also write the gradients (3 int8 per sample, x fastest)");

  CLI::App* infoCmd = app.add_subcommand("info", "describe a codec file: layout, padding, statistics");
  infoCmd->add_option("--codec", info->codec, "timevarying or leb")->required();
  infoCmd->add_option("--input", info->input, "file to describe")->required();

  return {{encodeCmd, [encode] { return runEncode(*encode); }},
          {decodeCmd, [decode] { return runDecode(*decode); }},
          {infoCmd, [info] { return runInfo(*info); }}};
}

}  // namespace voxref::cli
