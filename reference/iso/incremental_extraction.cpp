#include "reference/iso/incremental_extraction.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace voxref::ref {

std::uint32_t IncrementalExtraction::VertexStore::make(const MeshVertex& v, std::uint64_t key, int axis) {
  std::uint32_t id;
  if (!freeIds.empty()) {
    id = freeIds.back();
    freeIds.pop_back();
    positions[id] = v.position;
    normals[id] = v.normal;
  } else {
    id = static_cast<std::uint32_t>(positions.size());
    positions.push_back(v.position);
    normals.push_back(v.normal);
    meta.emplace_back();
  }
  Meta& m = meta[id];
  m = Meta{};
  m.key = key;
  m.clipAxis = static_cast<std::int8_t>(axis);
  m.alive = true;
  made.push_back(id);
  return id;
}

// Drops one reference; a vertex nothing uses any more leaves the store.
void IncrementalExtraction::VertexStore::release(std::uint32_t v) {
  if (--meta[v].refs == 0) drop(v);
}

// A vertex leaves the store (a clipped one drops its references on its edge's vertices).
void IncrementalExtraction::VertexStore::drop(std::uint32_t v) {
  Meta& m = meta[v];
  m.alive = false;
  freeIds.push_back(v);
  if (m.clipAxis < 0) {
    crossingIds.erase(m.key);
  } else {
    clipIds[static_cast<std::size_t>(m.clipAxis)].erase(m.key);
    release(m.ends[0]);
    release(m.ends[1]);
  }
}

struct IncrementalExtraction::StoreView {
  IncrementalExtraction& x;
  std::uint32_t crossing(const TetCorner& out, const TetCorner& in) {
    const std::uint64_t key = crossingKey(x.grid_, out, in, x.iso_);
    if (const std::uint32_t* known = x.store_.crossingIds.find(key)) return *known;
    const std::uint32_t v = x.store_.make(crossingVertex(out, in, x.iso_), key, -1);
    x.store_.crossingIds.try_emplace(key, v);
    return v;
  }
  std::uint32_t clipVertex(std::uint32_t a, std::uint32_t b, int axis) {
    VertexStore& s = x.store_;
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    auto& ids = s.clipIds[static_cast<std::size_t>(axis)];
    if (const std::uint32_t* known = ids.find(key)) return *known;
    const MeshVertex va{s.positions[a], s.normals[a]}, vb{s.positions[b], s.normals[b]};
    const double hi = x.clipHi_[axis];
    const std::uint32_t v =
        s.make(va.position[axis] <= hi ? clippedVertex(va, vb, axis, hi) : clippedVertex(vb, va, axis, hi), key, axis);
    s.meta[v].ends = {a, b};
    ++s.meta[a].refs;
    ++s.meta[b].refs;
    ids.try_emplace(key, v);
    return v;
  }
  const glm::dvec3& position(std::uint32_t v) const { return x.store_.positions[v]; }
};

IncrementalExtraction::IncrementalExtraction(const LebGrid& grid, const Dims3& volumeDims, const DiamondRanges* bounds,
                                             double isovalue)
    : grid_(makeLebGrid(grid.k)),
      dims_(volumeDims),
      clipHi_{volumeDims[0] - 1, volumeDims[1] - 1, volumeDims[2] - 1},
      bounds_(bounds),
      iso_(isovalue),
      order_(grid_) {
  requireIndexedGrid(grid_, "incremental extraction");
  if (bounds != nullptr && bounds->lebGrid().k != grid_.k)
    throw std::invalid_argument("incremental extraction: the bounds' grid and the mesh's grid differ");
  for (const int extent : volumeDims)
    if (extent < 1 || extent > grid_.pointsPerAxis())
      throw std::invalid_argument("incremental extraction: a volume of " + dimsText(volumeDims) +
                                  " samples does not fit the grid of " + std::to_string(grid_.pointsPerAxis()) +
                                  " points per axis");
}

void IncrementalExtraction::release(const Emitted& e) {
  if (!e.overflows()) {
    for (std::uint32_t i = 0; i < e.count; ++i) store_.release(e.ids[i]);
    return;
  }
  const auto o = overflow_.find(e.overflowKey());
  for (const std::uint32_t v : o->second) store_.release(v);
  overflow_.erase(o);
}

namespace {

std::array<std::int16_t, 3> narrow(const GridPoint& p) {
  return {static_cast<std::int16_t>(p[0]), static_cast<std::int16_t>(p[1]), static_cast<std::int16_t>(p[2])};
}
GridPoint widen(const std::array<std::int16_t, 3>& p) { return {p[0], p[1], p[2]}; }

}  // namespace

int IncrementalExtraction::creatorSlotOf(const Leaf& l) {
  return (l.bits & kHasCreator) ? static_cast<int>((l.bits >> kCreatorSlotShift) & 3) : -1;
}

GridPoint IncrementalExtraction::creatorOf(const Leaf& l) {
  const int slot = creatorSlotOf(l);
  return slot < 0 ? GridPoint{-1, -1, -1} : widen(l.v[static_cast<std::size_t>(slot)]);
}

GridPoint IncrementalExtraction::splitVertexOf(const Leaf& l) {
  const auto [i, j] = kTetrahedronEdges[(l.bits >> kEdgeShift) & 7];
  return evenMidpoint(widen(l.v[static_cast<std::size_t>(i)]), widen(l.v[static_cast<std::size_t>(j)]));
}

// extractIsosurface's step for one leaf: skipped when its diamond's range excludes the isovalue,
// else its corners read and, where they cross, its triangles made against the store.
void IncrementalExtraction::add(const LeafVisit& leaf, GridField& field) {
  Leaf kept;
  for (std::size_t k = 0; k < 4; ++k) kept.v[k] = narrow(leaf.t.v[k]);
  kept.bits = leaf.path;
  if (leaf.creatorSlot >= 0)
    kept.bits |= kHasCreator | static_cast<std::uint64_t>(leaf.creatorSlot) << kCreatorSlotShift;
  if (leaf.hasSplitVertex) {
    const auto e = static_cast<std::uint64_t>(
        std::find(kTetrahedronEdges.begin(), kTetrahedronEdges.end(), leaf.longest) - kTetrahedronEdges.begin());
    kept.bits |= kHasSplitVertex | e << kEdgeShift;
  }
  const GridPoint& diamond = leaf.diamond();
  const bool read = bounds_ == nullptr || diamond[0] < 0 || bounds_->mayContain(diamond, iso_);
  if (read) {
    kept.bits |= kRead;
    if (march(leaf, field)) kept.bits |= kCrossing;
    ++readLeaves_;
    ++lastReads_;
  }
  nextLeaves_.push_back(kept);
}

// The corners read, and where they cross the isovalue the triangles made against the store and
// appended to nextEmitted_; returns whether the leaf has triangles.
bool IncrementalExtraction::march(const LeafVisit& leaf, GridField& field) {
  const Tetrahedron& t = leaf.t;
  std::array<FieldSample, 4> f;
  int inside = 0;  // the builder's test (marching_tetrahedra.h)
  for (std::size_t k = 0; k < 4; ++k) {
    f[k] = field.at(t.v[k]);
    inside += f[k].value >= iso_ ? 1 : 0;
  }
  if (inside == 0 || inside == 4) return false;
  std::array<TetCorner, 4> corners;
  for (std::size_t k = 0; k < 4; ++k) corners[k] = {t.v[k], f[k].value, gradientVector(f[k].gradient)};
  std::array<std::uint32_t, 24> ids;  // two triangles, each clipped into at most four
  std::size_t count = 0;
  store_.made.clear();
  StoreView view{*this};
  marchTetrahedron(corners, iso_, clipHi_, grid_.side(), view, [&](const std::array<std::uint32_t, 3>& tri) {
    for (const std::uint32_t v : tri) ids[count++] = v;
  });
  for (std::size_t i = 0; i < count; ++i) ++store_.meta[ids[i]].refs;
  // Vertices made for this leaf that none of its triangles uses (clipped away) leave at once, the
  // clipped ones first (they hold their edge's vertices).
  for (auto it = store_.made.rbegin(); it != store_.made.rend(); ++it)
    if (store_.meta[*it].alive && store_.meta[*it].refs == 0) store_.drop(*it);
  if (count == 0) return false;
  Emitted e;
  const GridPoint& diamond = leaf.diamond();
  e.diamond = diamond[0] >= 0 ? static_cast<DiamondId>(order_.index(diamond)) : kNoDiamond;
  e.count = static_cast<std::uint32_t>(count);
  if (!e.overflows()) {
    std::copy(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count), e.ids.begin());
  } else {
    e.ids[0] = static_cast<std::uint32_t>(leaf.path);
    e.ids[1] = static_cast<std::uint32_t>(leaf.path >> 32);
    overflow_[leaf.path].assign(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count));
  }
  nextEmitted_.push_back(e);
  return true;
}

void IncrementalExtraction::setIsovalue(double isovalue) {
  iso_ = isovalue;
  leaves_.clear();
  readLeaves_ = 0;
  emitted_.clear();
  overflow_.clear();
  store_ = VertexStore{};
}

void IncrementalExtraction::addAll(const DiamondMesh& mesh, GridField& field) {
  readLeaves_ = 0;
  mesh.forEachLeafVisit([&](const LeafVisit& v) { add(v, field); });
}

void IncrementalExtraction::follow(const DiamondMesh& mesh, GridField& field) {
  std::size_t e = 0;  // the old leaves' entries in emitted_ follow their order
  auto forget = [&](const Leaf& old) {
    if (old.bits & kRead) --readLeaves_;
    if (old.bits & kCrossing) release(emitted_[e++]);
  };
  auto addLeaf = [&](const LeafVisit& v) { add(v, field); };
  for (std::size_t i = 0; i < leaves_.size();) {
    const Leaf& old = leaves_[i];
    const std::uint64_t path = pathOf(old);
    if ((old.bits & kHasCreator) && !mesh.isSplitPoint(creatorOf(old))) {
      // Its parent was merged: the leaf above it on its path replaces it and every old leaf below
      // that one (they follow it in path order).
      const LeafVisit above = mesh.leafOnPath(path);
      const std::uint64_t depth = above.path & kLeafPathDepthMask;
      const std::uint64_t prefix = ~((std::uint64_t{1} << (61 - depth)) - 1);  // clears the flags too
      for (; i < leaves_.size() && (leaves_[i].bits & prefix) == (above.path & prefix) &&
             (leaves_[i].bits & kLeafPathDepthMask) > depth;
           ++i)
        forget(leaves_[i]);
      addLeaf(above);
      continue;
    }
    if (old.bits & kHasSplitVertex) {
      const GridPoint m = splitVertexOf(old);
      if (mesh.isSplitPoint(m)) {  // split: new leaves below it
        Tetrahedron t;
        for (std::size_t k = 0; k < 4; ++k) t.v[k] = widen(old.v[k]);
        const LeafVisit start{
            t, creatorOf(old), path, true, m, kTetrahedronEdges[(old.bits >> kEdgeShift) & 7], creatorSlotOf(old)};
        forget(old);
        mesh.forEachLeafBelow(start, addLeaf);
        ++i;
        continue;
      }
    }
    nextLeaves_.push_back(old);  // the same leaf
    if (old.bits & kCrossing) nextEmitted_.push_back(emitted_[e++]);
    ++i;
  }
  if (e != emitted_.size()) throw std::logic_error("incremental extraction: kept triangles without their leaf");
}

IsoMesh IncrementalExtraction::update(const DiamondMesh& mesh, GridField& field, ExtractionStats* stats) {
  if (mesh.grid().k != grid_.k || field.grid().k != grid_.k)
    throw std::invalid_argument("incremental extraction: the mesh's or the field's grid is not the extraction's");
  if (field.volumeDims() != dims_)
    throw std::invalid_argument("incremental extraction: the field's volume is " + dimsText(field.volumeDims()) +
                                ", the extraction's " + dimsText(dims_));
  lastReads_ = 0;
  nextLeaves_.clear();
  nextEmitted_.clear();
  // Room for twice the last leaves: pages never touched cost nothing, and the lists do not move
  // while they are built (each move copies them and, on a new mapping, faults again).
  nextLeaves_.reserve(2 * leaves_.size());
  nextEmitted_.reserve(2 * emitted_.size());
  if (leaves_.empty()) {
    addAll(mesh, field);
  } else {
    follow(mesh, field);
  }
  std::swap(leaves_, nextLeaves_);
  std::swap(emitted_, nextEmitted_);

  std::size_t indexCount = 0;
  for (const Emitted& e : emitted_) indexCount += e.count;
  std::vector<std::uint32_t> indices;
  std::vector<DiamondId> diamonds;
  indices.reserve(indexCount);
  diamonds.reserve(indexCount / 3);
  for (const Emitted& e : emitted_) {
    if (!e.overflows()) {
      indices.insert(indices.end(), e.ids.begin(), e.ids.begin() + e.count);
    } else {
      const std::vector<std::uint32_t>& ids = overflow_.at(e.overflowKey());
      indices.insert(indices.end(), ids.begin(), ids.end());
    }
    diamonds.insert(diamonds.end(), e.count / 3, e.diamond);
  }
  IsoMesh out = assembleIsoMesh(std::move(indices), std::move(diamonds), store_.positions, store_.normals, &scratch_);
  if (stats != nullptr) *stats = {leaves_.size(), readLeaves_, out.triangleCount()};
  return out;
}

}  // namespace voxref::ref
