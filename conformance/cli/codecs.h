// The codecs of voxref encode | decode | info, one file each (codec_<name>.cpp); cmd_codec.cpp
// picks one by --codec.
#pragma once

#include <string>

#include "conformance/cli/commands.h"
#include "reference/common/volume.h"

namespace voxref::cli {

int encodeTimeVaryingCommand(const EncodeOptions& o);
int decodeTimeVaryingCommand(const DecodeOptions& o);
int infoTimeVaryingCommand(const InfoOptions& o);

int encodeLebCommand(const EncodeOptions& o);
int decodeLebCommand(const DecodeOptions& o);
int infoLebCommand(const InfoOptions& o);

inline std::string dimsText(const ref::Dims3& d) { return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]); }

}  // namespace voxref::cli
