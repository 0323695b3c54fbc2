// voxref encode | decode | info --codec NAME: the codecs on the user's own volumes.
#include "conformance/cli/codecs.h"
#include "conformance/framework/runner.h"

namespace voxref::cli {
namespace {

enum class Codec { TimeVarying, Leb };

Codec codecOf(const std::string& name) {
  if (name == "timevarying") return Codec::TimeVarying;
  if (name == "leb") return Codec::Leb;
  throw conf::UsageError("unknown codec '" + name + "' (known: timevarying, leb)");
}

}  // namespace

int runEncode(const EncodeOptions& o) { return codecOf(o.codec) == Codec::Leb ? encodeLebCommand(o) : encodeTimeVaryingCommand(o); }
int runDecode(const DecodeOptions& o) { return codecOf(o.codec) == Codec::Leb ? decodeLebCommand(o) : decodeTimeVaryingCommand(o); }
int runInfo(const InfoOptions& o) { return codecOf(o.codec) == Codec::Leb ? infoLebCommand(o) : infoTimeVaryingCommand(o); }

}  // namespace voxref::cli
