#include "conformance/bench/leb_datasets.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <unordered_set>

#include "conformance/io/raw_volume.h"
#include "reference/common/fields.h"
#include "reference/leb/gradients.h"

namespace voxref::conf {
namespace {

// The paper's resampling of the engine to 256^3 ("resampled to 256^3 with the cell aspect ratios
// appropriately adjusted at runtime"), as voxref makes it: the original slices at even z, and at
// odd z the rounded-down mean of the slices around (the last slice repeated). The inserted slices
// are exactly what the split-edge predictor predicts along z, which is why this volume compresses
// better than the one as stored.
ref::Volume<std::uint8_t> doubleSlices(const ref::Volume<std::uint8_t>& v) {
  const ref::Dims3 d = v.dims();
  ref::Volume<std::uint8_t> out({d[0], d[1], 2 * d[2]});
  for (int z = 0; z < 2 * d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) {
        const int lo = z / 2, hi = std::min(lo + 1, d[2] - 1);
        out.at(x, y, z) =
            z % 2 == 0 ? v.at(x, y, lo) : static_cast<std::uint8_t>((v.at(x, y, lo) + v.at(x, y, hi)) / 2);
      }
  return out;
}

}  // namespace

LebDataset sharedLebDataset(const BenchOptions& o, const std::string& name, const std::string& file,
                            const ref::Dims3& dims, bool doubled) {
  LebDataset d;
  d.name = name;
  const std::filesystem::path path = benchVolumes(o) / file;
  if (!std::filesystem::exists(path)) {
    d.missing = path.string() + " is missing (give the folder with --volumes)";
    return d;
  }
  const ref::Volume<std::uint8_t> v = io::readRawVolumeU8(path, dims);
  d.volume = ref::widenToU16(doubled ? doubleSlices(v) : v);
  return d;
}

LebDataset buckyballLebDataset(int side) {
  LebDataset d;
  d.name = "Gaussian buckyball " + std::to_string(side) + "^3 (synthetic)";
  d.volume = ref::widenToU16(ref::sampleFieldU8(ref::analyticField("gaussian_buckyball"), {side, side, side}));
  return d;
}

std::vector<LebDataset> lebDatasets(const BenchOptions& o) {
  std::vector<LebDataset> v;
  if (o.quick) {
    v.push_back(sharedLebDataset(o, "nucleon 41^3", "nucleon_41x41x41_uint8.raw.gz", {41, 41, 41}));
    v.push_back(buckyballLebDataset(48));
    return v;
  }
  v.push_back(
      sharedLebDataset(o, "engine 256x256x128 (as stored)", "engine_256x256x128_uint8.raw.gz", {256, 256, 128}));
  v.push_back(sharedLebDataset(o, "engine 256^3 (slices doubled, as the paper)", "engine_256x256x128_uint8.raw.gz",
                               {256, 256, 128}, true));
  v.back().paper[0] = "2.6";
  v.back().paper[1] = "4.35";
  v.back().paper[2] = "2.22";
  v.push_back(sharedLebDataset(o, "hydrogen_atom 128^3", "hydrogen_atom_128x128x128_uint8.raw.gz", {128, 128, 128}));
  v.push_back(buckyballLebDataset(256));
  v.back().paper[0] = "3.071 (1024^3)";
  v.back().paper[1] = "5.51";
  v.back().paper[2] = "2.6";
  return v;
}

std::string dataBytes(const ref::Volume<std::uint16_t>& v, int bits) {
  std::string b;
  b.reserve(v.data().size() * static_cast<std::size_t>(bits / 8));
  for (std::uint16_t s : v.data()) {
    b.push_back(static_cast<char>(s & 0xff));
    if (bits == 16) b.push_back(static_cast<char>(s >> 8));
  }
  return b;
}

std::string gradientBytes(const ref::Volume<std::uint16_t>& v) {
  const std::vector<std::int8_t> g = ref::quantizedGradients(v);
  return std::string(reinterpret_cast<const char*>(g.data()), g.size());
}

double repeatedRowShare(std::string_view bytes, std::size_t rowBytes) {
  if (rowBytes == 0 || bytes.size() % rowBytes != 0)
    throw std::invalid_argument("repeatedRowShare: rows of " + std::to_string(rowBytes) + " bytes do not divide " +
                                std::to_string(bytes.size()) + " bytes");
  std::unordered_set<std::string_view> seen;
  std::size_t rows = 0, repeats = 0;
  for (std::size_t at = 0; at < bytes.size(); at += rowBytes) {
    const std::string_view row = bytes.substr(at, rowBytes);
    if (row.find_first_not_of(row.front()) == std::string_view::npos) continue;  // one byte repeated
    ++rows;
    if (!seen.insert(row).second) ++repeats;
  }
  return rows == 0 ? 0.0 : static_cast<double>(repeats) / static_cast<double>(rows);
}

std::vector<LebDataset> folderLebDatasets(const BenchOptions& o) {
  std::vector<LebDataset> v;
  if (!o.quick) {
    v.push_back(sharedLebDataset(o, "engine 256x256x128", "engine_256x256x128_uint8.raw.gz", {256, 256, 128}));
    v.push_back(sharedLebDataset(o, "hydrogen_atom 128^3", "hydrogen_atom_128x128x128_uint8.raw.gz", {128, 128, 128}));
  }
  v.push_back(sharedLebDataset(o, "nucleon 41^3", "nucleon_41x41x41_uint8.raw.gz", {41, 41, 41}));
  v.push_back(sharedLebDataset(o, "bucky 32^3", "bucky_32x32x32_uint8.raw.gz", {32, 32, 32}));
  return v;
}

const LebDataset* firstAvailable(const std::vector<LebDataset>& sets) {
  for (const LebDataset& d : sets)
    if (d.missing.empty()) return &d;
  return nullptr;
}

}  // namespace voxref::conf
