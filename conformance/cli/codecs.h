// The codecs of voxref encode | decode | info, one file each (codec_<name>.cpp); cmd_codec.cpp
// declares the three commands' options and picks a codec by --codec.
#pragma once

#include <string>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reference/common/volume.h"

namespace voxref::cli {

// The options of encode, decode and info (their command: cmd_codec.cpp).
struct EncodeOptions {
  std::string codec;
  std::vector<std::filesystem::path> inputs;  // one raw volume per time step
  std::vector<int> dims;
  std::string type = "uint8";
  bool plume = false;  // the synthetic discharge plume instead of files
  double sparseness = 0.0;
  int plumeSide = 128, plumeSteps = 36;
  std::string transfer = "plume";
  std::string level = "auto";
  std::string encoding = "normalized_rgba8";
  std::string alphaOne = "refine";
  int pageBits = 12;                // leb: 2^pageBits points per page
  std::string lebCoder = "lead1";   // leb: the pages' entropy stage, lead1 (the paper's) or adaptive
  bool noGradients = false;         // leb: data channel only
  bool deriveGradients = false;     // leb: data channel only, the gradients derived when decoded
  std::string mirror = "off";       // leb: off, or auto (fold the mirror planes found: a mirrored stream)
  std::filesystem::path boundsOut;  // leb: also write the per-diamond bounds (reference/iso/BOUNDS_FORMAT.md)
  std::filesystem::path out;
};
struct DecodeOptions {
  std::string codec;
  std::filesystem::path input, out;
  std::optional<int> step;             // timevarying; none: every step
  std::filesystem::path gradientsOut;  // leb
};
struct InfoOptions {
  std::string codec;
  std::filesystem::path input;
};

int encodeTimeVaryingCommand(const EncodeOptions& o);
int decodeTimeVaryingCommand(const DecodeOptions& o);
int infoTimeVaryingCommand(const InfoOptions& o);

int encodeLebCommand(const EncodeOptions& o);
int decodeLebCommand(const DecodeOptions& o);
int infoLebCommand(const InfoOptions& o);

using ref::dimsText;

}  // namespace voxref::cli
