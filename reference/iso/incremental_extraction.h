// Isosurface extraction that keeps what it made from one frame to the next (Gregorski et al.
// 2004, section 4: refinement splits and merges a bounded number of diamonds a frame, so most leaf
// tetrahedra, and the triangles in them, are those of the frame before).
//
// A leaf tetrahedron is named by its path in the hierarchy (DiamondMesh::forEachLeafVisit),
// and a path names one tetrahedron, with the same corners in the same order, in every mesh that
// has it. So a leaf's triangles depend only on its path, the field and the isovalue. The
// extraction keeps the last update's leaves in path order, each with its triangles (or its having
// none); an update walks that list once, and for each old leaf asks the mesh two questions (is
// the tetrahedron it is a half of still split, is it split itself):
//   - both no: the same leaf, kept as it is, without reading the field;
//   - it is split now: the leaves below it are new (DiamondMesh::forEachLeafBelow);
//   - its parent was merged: the leaf above it on its path is new (DiamondMesh::leafOnPath), and
//     the old leaves below that one are gone.
// A new leaf is read and marched as extractIsosurface does. The vertices live in a persistent store
// (crossing vertices keyed as the builder keys them, clipped ones by their edge), counted by the
// triangles that use them, and each update assembles the mesh from the kept triangles in path
// order, which is extractIsosurface's order, with the builder's own code (marching_tetrahedra.h:
// marchTetrahedron, assembleIsoMesh).
//
// Exactness: update(mesh, field) returns what extractIsosurface(mesh, field, bounds, isovalue,
// stats) returns, bit for bit (positions, normals, indices, diamonds and statistics), provided the
// field is the same at every update (tests/reference/iso/incremental_extraction_test.cpp checks it
// after every step of random and view-driven split and merge sequences, with clipping and values
// equal to the isovalue). Single-threaded and deterministic.
//
// Cost of an update: two bit lookups per old leaf, the reads and marching of the new leaves, and
// one pass over the kept triangles; the first update (and the first after a new isovalue) walks
// the mesh from its roots. Memory: 32 bytes per leaf and per crossing leaf, twice (the lists being
// built beside the last), and about 100 per vertex of the store with its hash table slots. The
// lists and the store's arrays sit on huge pages (huge_page_allocator.h): every frame writes the
// lists anew, and where they grow each first touch of a 4 KiB page would fault (about 7 us each
// on the virtual machines of docs/iso.md, a seventh of the engine's extraction before).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "reference/common/flat_u64_map.h"
#include "reference/common/huge_page_allocator.h"
#include "reference/common/volume.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/extraction.h"
#include "reference/iso/grid_field.h"
#include "reference/iso/iso_mesh.h"
#include "reference/iso/marching_tetrahedra.h"
#include "reference/leb/diamond_mesh.h"
#include "reference/leb/hz_order.h"

namespace voxref::ref {

class IncrementalExtraction {
 public:
  // For the meshes of `grid` and a field whose volume has `volumeDims` (the clip box, as
  // extractIsosurface clips). bounds may be null (every leaf is read); they must outlive the
  // extraction. Throws std::invalid_argument when the bounds' grid is not `grid` or the volume
  // does not fit it.
  IncrementalExtraction(const LebGrid& grid, const Dims3& volumeDims, const DiamondRanges* bounds, double isovalue);

  // The isosurface of the mesh as it is now: extractIsosurface's result. Throws
  // std::invalid_argument when the mesh's or the field's grid, or the field's volume, is not the
  // extraction's.
  IsoMesh update(const DiamondMesh& mesh, GridField& field, ExtractionStats* stats = nullptr);
  // A new isovalue: the next update reads every leaf again.
  void setIsovalue(double isovalue);

  // Leaf tetrahedra whose corners the last update read (the new ones the bounds did not skip).
  std::size_t lastUpdateReads() const { return lastReads_; }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  // A leaf of the last update, in 32 bytes (every frame copies the list, and on these machines
  // every new page of it costs a fault): its corners and its path, whose unused bits 8..16 hold
  // which corner is its creator (the split vertex of the tetrahedron it is a half of), which edge is
  // its longest (its split vertex is that edge's midpoint), whether it has either, whether its
  // corners were read (the bounds held the isovalue) and whether it has triangles (its entry in
  // emitted_, which follows the leaves' order).
  struct Leaf {
    std::array<std::array<std::int16_t, 3>, 4> v{};
    std::uint64_t bits = 0;
  };
  static constexpr int kCreatorSlotShift = 8, kEdgeShift = 11;
  static constexpr std::uint64_t kHasCreator = std::uint64_t{1} << 10, kHasSplitVertex = std::uint64_t{1} << 14,
                                 kRead = std::uint64_t{1} << 15, kCrossing = std::uint64_t{1} << 16,
                                 kLeafFlags = std::uint64_t{0x1ff} << 8;
  static std::uint64_t pathOf(const Leaf& l) { return l.bits & ~kLeafFlags; }
  static int creatorSlotOf(const Leaf& l);  // -1 for a root
  static GridPoint creatorOf(const Leaf& l);
  static GridPoint splitVertexOf(const Leaf& l);

  // The triangles of one crossing leaf, in 32 bytes: their vertices when there are at most six,
  // else the leaf's path (ids[0] its low half, ids[1] its high half), under which overflow_ holds
  // them, so that neither the assembly nor a release looks for the leaf.
  struct Emitted {
    DiamondId diamond = kNoDiamond;
    std::uint32_t count = 0;  // vertices, 3 per triangle
    std::array<std::uint32_t, 6> ids{};
    bool overflows() const { return count > ids.size(); }
    std::uint64_t overflowKey() const { return (std::uint64_t{ids[1]} << 32) | ids[0]; }
  };

  // The persistent vertex store (marchTetrahedron's store), counted by the triangles that use a
  // vertex and by the clipped vertices made on its edges.
  struct VertexStore {
    struct Meta {
      std::uint64_t key = 0;
      std::array<std::uint32_t, 2> ends{kNone, kNone};  // a clipped vertex's edge
      std::uint32_t refs = 0;
      std::int8_t clipAxis = -1;  // -1: a crossing vertex
      bool alive = false;
    };
    HugePageVector<glm::dvec3> positions, normals;
    HugePageVector<Meta> meta;
    std::vector<std::uint32_t> freeIds;
    FlatU64Map<std::uint32_t> crossingIds;
    std::array<FlatU64Map<std::uint32_t>, 3> clipIds;
    std::vector<std::uint32_t> made;  // made while marching the current tetrahedron

    std::uint32_t make(const MeshVertex& v, std::uint64_t key, int axis);
    void release(std::uint32_t v);
    void drop(std::uint32_t v);
  };
  struct StoreView;  // marchTetrahedron's view of the store

  void release(const Emitted& e);
  // extractIsosurface's step for a new leaf: appended to nextLeaves_, its triangles (if any) to
  // nextEmitted_.
  void add(const LeafVisit& leaf, GridField& field);
  bool march(const LeafVisit& leaf, GridField& field);
  // The mesh's leaves from its roots (the first update, or the first after a new isovalue).
  void addAll(const DiamondMesh& mesh, GridField& field);
  // The leaves of the last update against the mesh now.
  void follow(const DiamondMesh& mesh, GridField& field);

  LebGrid grid_;
  Dims3 dims_;
  GridPoint clipHi_;
  const DiamondRanges* bounds_;
  double iso_;
  HzOrder order_;
  HugePageVector<Leaf> leaves_, nextLeaves_;       // the last update's leaves, paths rising; a buffer
  HugePageVector<Emitted> emitted_, nextEmitted_;  // the crossing leaves' triangles, paths rising
  std::size_t readLeaves_ = 0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> overflow_;
  VertexStore store_;
  AssemblyScratch scratch_;
  std::size_t lastReads_ = 0;
};

}  // namespace voxref::ref
