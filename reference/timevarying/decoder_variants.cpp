#include "reference/timevarying/decoder_variants.h"

#include <string>

namespace voxref::ref {

std::string_view name(DecoderVariant v) {
  switch (v) {
    case DecoderVariant::Literal:
      return "literal";
    case DecoderVariant::Paper:
      return "paper";
    case DecoderVariant::TexelCentre:
      return "texel_centre";
    case DecoderVariant::TexelFetch:
      return "texel_fetch";
  }
  return "?";
}

std::optional<DecoderVariant> parseDecoderVariant(std::string_view s) {
  for (DecoderVariant v :
       {DecoderVariant::Literal, DecoderVariant::Paper, DecoderVariant::TexelCentre, DecoderVariant::TexelFetch})
    if (name(v) == s) return v;
  return std::nullopt;
}

std::string decoderIncompatibility(DecoderVariant v, const TimeVaryingLayout& l, IndexEncoding e) {
  switch (v) {
    case DecoderVariant::Literal:
      if (e != IndexEncoding::NormalizedRgba8) return "the literal decoder reads normalized_rgba8 indices";
      if (l.side != 128 || l.level != 4 || l.indexSlots != 8 || l.blockSlots != 16)
        return "the literal decoder's macros (DR 8, TEX_DIM 128) describe the paper's layout of level 4 on 128^3 only";
      return {};
    case DecoderVariant::Paper:
      if (e == IndexEncoding::BlockRgba8) return "the paper's decoder reads normalized indices, not block_rgba8";
      return {};
    case DecoderVariant::TexelCentre:
    case DecoderVariant::TexelFetch:
      if (e != IndexEncoding::BlockRgba8) return "the " + std::string(name(v)) + " decoder reads block_rgba8 indices";
      return {};
  }
  return "unknown decoder";
}

}  // namespace voxref::ref
