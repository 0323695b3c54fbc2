// Writes a seed corpus of valid LEB streams for the fuzz target: small volumes of each kind the
// decoder handles (8 and 16 bits, with and without gradients, padded and not, tiny pages), with
// each coder (lead-1: version 2; adaptive: version 3; context: version 4, with and without a
// gradients channel); and mirrored streams around each coder's (reference/leb/mirror_stream.h).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <vector>

#include "reference/leb/gradients.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/mirror_stream.h"

int main(int argc, char** argv) {
  using namespace voxref::ref;
  if (argc != 2) {
    std::cerr << "usage: make_leb_seeds DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  auto write = [&](const std::string& name, const Volume<std::uint16_t>& v, int bits, int pageBits, bool gradients,
                   LebCoder coder = LebCoder::Lead1, bool derive = false) {
    LebEncodeOptions o;
    o.pageBits = pageBits;
    o.gradients = gradients;
    o.coder = coder;
    o.deriveGradients = derive;
    std::ofstream(dir / name, std::ios::binary) << encodeLeb(v, bits, o);
  };
  std::mt19937 rng(1);
  Volume<std::uint16_t> smooth({9, 7, 5}), noise({4, 4, 4}), wide({5, 5, 3});
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 9; ++x)
        smooth.at(x, y, z) = static_cast<std::uint16_t>(128 + 100 * std::sin(0.5 * x + 0.3 * y - 0.2 * z));
  for (auto& s : noise.data()) s = static_cast<std::uint16_t>(rng() & 255);
  for (auto& s : wide.data()) s = static_cast<std::uint16_t>(rng() & 65535);
  write("smooth_gradients.vxleb", smooth, 8, 4, true);
  write("smooth_data_only.vxleb", smooth, 8, 6, false);
  write("noise.vxleb", noise, 8, 4, true);
  write("wide16.vxleb", wide, 16, 4, true);
  write("constant.vxleb", Volume<std::uint16_t>({3, 3, 3}, 7), 8, 4, false);
  write("single.vxleb", Volume<std::uint16_t>({1, 1, 1}, 200), 8, 4, true);
  write("adaptive_smooth_gradients.vxleb", smooth, 8, 4, true, LebCoder::Adaptive);
  write("adaptive_noise.vxleb", noise, 8, 6, true, LebCoder::Adaptive);
  write("adaptive_wide16.vxleb", wide, 16, 4, false, LebCoder::Adaptive);
  write("derived_smooth.vxleb", smooth, 8, 4, true, LebCoder::Lead1, true);  // header byte 23 = 1
  write("adaptive_derived_wide16.vxleb", wide, 16, 4, true, LebCoder::Adaptive, true);
  write("context_derived_smooth.vxleb", smooth, 8, 4, true, LebCoder::Context, true);  // version 4
  write("context_noise.vxleb", noise, 8, 6, false, LebCoder::Context);
  write("context_wide16.vxleb", wide, 16, 4, false, LebCoder::Context);
  write("context_smooth_gradients.vxleb", smooth, 8, 4, true, LebCoder::Context);  // "Context gradient pages"
  write("context_noise_gradients.vxleb", noise, 8, 6, true, LebCoder::Context);
  // Mirrored: the smooth volume made its own mirror image in x (sum 8) and z (sum 3), with one
  // point off its image; the wide one in y (sum 4); noise across the centre of x (sum 31) with its
  // gradients derived, and stored with one more point off its mirrored gradient.
  auto writeMirrored = [&](const std::string& name, Volume<std::uint16_t> v, int bits, const LebMirrorPlanes& planes,
                           LebCoder coder, LebMirrorGradients gradients, bool exception) {
    const Dims3 d = v.dims();
    for (int z = 0; z < d[2]; ++z)
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x)
          v.at(x, y, z) = v.at(lebMirrorImage(x, planes.sum[0]), lebMirrorImage(y, planes.sum[1]),
                               lebMirrorImage(z, planes.sum[2]));
    if (exception) v.at(d[0] - 1, 0, 0) = static_cast<std::uint16_t>(v.at(d[0] - 1, 0, 0) ^ 1);
    LebEncodeOptions o;
    o.pageBits = 4;
    o.coder = coder;
    o.gradients = gradients != LebMirrorGradients::None;
    o.deriveGradients = gradients == LebMirrorGradients::Derived;
    std::vector<std::int8_t> g;
    if (gradients == LebMirrorGradients::Stored) {
      g = quantizedGradients(v);
      g[3 * v.index(d[0] - 1, 1, 1) + 2] ^= 1;
    }
    std::ofstream(dir / name, std::ios::binary) << encodeMirroredLeb(v, bits, planes, o, g);
  };
  Volume<std::uint16_t> big({32, 7, 5});  // 2^8 mirrored points at least, so one exception fits
  for (auto& s : big.data()) s = static_cast<std::uint16_t>(rng() & 255);
  using enum LebMirrorGradients;
  writeMirrored("mirrored_lead1.vxleb", smooth, 8, {{8, kNoLebMirror, 3}}, LebCoder::Lead1, None, false);
  writeMirrored("mirrored_context_exception.vxleb", big, 8, {{31, kNoLebMirror, 3}}, LebCoder::Context, Derived, true);
  writeMirrored("mirrored_adaptive_wide16.vxleb", wide, 16, {{kNoLebMirror, 4, kNoLebMirror}}, LebCoder::Adaptive,
                Derived, false);
  writeMirrored("mirrored_context_stored.vxleb", big, 8, {{31, kNoLebMirror, kNoLebMirror}}, LebCoder::Context, Stored,
                true);
  return 0;
}
