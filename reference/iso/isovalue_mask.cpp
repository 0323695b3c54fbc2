#include "reference/iso/isovalue_mask.h"

namespace voxref::ref {

IsovalueMask::IsovalueMask(const DiamondBounds& table, double isovalue) : table_(&table) { setIsovalue(isovalue); }

void IsovalueMask::setIsovalue(double isovalue) {
  isovalue_ = isovalue;
  const std::size_t n = table_->min.size();
  bits_.assign((n + 63) / 64, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (table_->holds(i, isovalue)) bits_[i >> 6] |= std::uint64_t{1} << (i & 63);
}

}  // namespace voxref::ref
