// The volumes of the LEB benchmarks: the real volumes of the volumes folder (benchVolumes) and
// the synthetic buckyball, as 16-bit volumes of 8-bit samples, and their bytes as the
// general-purpose baselines get them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "conformance/bench/bench.h"
#include "reference/common/volume.h"

namespace voxref::conf {

struct LebDataset {
  std::string name;
  std::string missing;  // why the data set could not be made (a file is missing)
  ref::Volume<std::uint16_t> volume;
  int bits = 8;
  std::string paper[3];  // Table 1: Data+G, Data, Grad
};

// A volume of the volumes folder (uint8, dims as its name says); `doubled`: the paper's resampling
// of the engine to 256^3 (odd slices the rounded-down mean of their neighbours). A missing file
// gives a data set with `missing` set, not an error.
LebDataset sharedLebDataset(const BenchOptions& o, const std::string& name, const std::string& file,
                            const ref::Dims3& dims, bool doubled = false);
// The Gaussian buckyball sampled at side^3.
LebDataset buckyballLebDataset(int side);
// Table 1's data sets (quick: nucleon 41^3 and the buckyball at 48^3).
std::vector<LebDataset> lebDatasets(const BenchOptions& o);
// Every volume of the volumes folder as stored (quick: the two small ones).
std::vector<LebDataset> folderLebDatasets(const BenchOptions& o);
const LebDataset* firstAvailable(const std::vector<LebDataset>& sets);

// The lengths of voxref's diffusion of the gradients (reference/leb/gradients.h,
// diffusedQuantizedGradients) that the benches measure for the paper's Table 1 conditions, which
// name neither the scheme nor its length.
inline constexpr int kPaperDiffusionSteps[] = {2, 8};

// The samples at 1 or 2 bytes (little endian), x fastest.
std::string dataBytes(const ref::Volume<std::uint16_t>& v, int bits);
// quantizedGradients(v) as bytes, 3 per sample.
std::string gradientBytes(const ref::Volume<std::uint16_t>& v);

// Of the rows of `bytes` (consecutive runs of rowBytes bytes; an x-row of a channel) that are not
// one byte repeated, the share that repeat an earlier row byte for byte: exact repeats at a
// distance, which an LZ coder (zstd, xz) copies and a predictor from neighbouring samples cannot
// see (a volume with mirror symmetry repeats most of its rows). 0 when no row qualifies. Throws
// std::invalid_argument when rowBytes is 0 or does not divide the size.
double repeatedRowShare(std::string_view bytes, std::size_t rowBytes);

}  // namespace voxref::conf
