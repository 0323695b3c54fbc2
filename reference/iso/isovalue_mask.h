// The bounds table's answer to "may this diamond hold the surface?" for one isovalue, kept as one
// bit per grid point: 2.1 MB for the engine's 257^3 grid against the table's 136 MB. Refinement asks
// it for every diamond it queues and the extraction for every new leaf; on the engine's orbit those
// lookups into the table were among the loads the frame waited on most (docs/iso.md).
//
// The answers are the table's, bit for bit: for the mask's isovalue from the bits, each made by
// the table's own test (DiamondBounds::holds); for any other isovalue from the table;
// errorOf is the table's. Not thread safe against setIsovalue.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/iso/diamond_bounds.h"

namespace voxref::ref {

class IsovalueMask final : public DiamondRanges {
 public:
  // The table must outlive the mask. Memory: one bit per entry of the table; one pass over it.
  IsovalueMask(const DiamondBounds& table, double isovalue);
  // The bits of another isovalue (one pass over the table).
  void setIsovalue(double isovalue);
  double isovalue() const { return isovalue_; }

  const LebGrid& lebGrid() const override { return table_->grid; }
  bool mayContain(const GridPoint& p, double isovalue) const override {
    if (isovalue != isovalue_) return table_->mayContain(p, isovalue);
    const std::uint64_t i = table_->grid.linearIndex(p);
    return (bits_[i >> 6] >> (i & 63)) & 1u;
  }
  float errorOf(const GridPoint& p) const override { return table_->errorOf(p); }

 private:
  const DiamondBounds* table_;
  double isovalue_ = 0.0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace voxref::ref
