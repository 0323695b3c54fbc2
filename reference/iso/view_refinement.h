// View-dependent refinement of the LEB diamond mesh with a split queue and a merge queue
// (Gregorski et al. 2004, section 4, after ROAM, Duchaineau et al. 1997).
//
// The split queue holds the leaf diamonds (not split, every parent split: their tetrahedra are
// in the mesh); the merge queue holds the split diamonds none of whose children is split. Both
// are ordered by the projected error of the diamond:
//     priority(d) = 0                                     if occluded(d) or the isovalue is outside
//                                                         [min(d), max(d)] (no surface inside);
//                 = error(d) * P / max(distance, radius)   otherwise,
// with error(d) from diamond_bounds.h (data units, read as a displacement of that many grid units),
// P = height / (2 tan(fov_y / 2)) the pixels per unit length at distance 1, distance from the eye
// to the diamond's split vertex and radius half the diagonal of its box. So the priority is an
// error in pixels. Every frame: priorities are recomputed for the new camera; the split with the
// highest priority is made while it is above the threshold and the split budget lasts (forced
// splits of parents count against the budget); then the merge with the lowest priority while it
// is at or below the threshold and the merge budget lasts. A merged diamond's priority is at or
// below the threshold, so it is not split again in the same frame, and a split one's is above
// it: no oscillation. Ties are broken by the grid index: deterministic.
// The mesh is conforming (crack-free) after every single split and merge (diamond_mesh.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "reference/common/flat_u64_map.h"
#include "reference/common/view_camera.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/leb/diamond_mesh.h"

namespace voxref::ref {

struct RefinementBudget {
  double threshold = 2.0;            // pixels
  std::size_t maxSplits = 1u << 20;  // per frame
  std::size_t maxMerges = 1u << 20;  // per frame
};

struct RefinementStats {
  std::size_t splits = 0, merges = 0;
  std::size_t splitQueue = 0, mergeQueue = 0;  // sizes after the frame
  bool budgetExhausted = false;                // a split above the threshold was left undone
};

class ViewRefinement {
 public:
  // The bounds must outlive the refinement.
  ViewRefinement(const DiamondRanges& bounds, double isovalue);

  const DiamondMesh& mesh() const { return mesh_; }
  double isovalue() const { return isovalue_; }
  void setIsovalue(double isovalue) { isovalue_ = isovalue; }

  // One frame. occluded(d) says whether diamond d was found occluded (its error counts as zero);
  // pass an empty function for none.
  RefinementStats update(const ViewCamera& camera, const RefinementBudget& budget,
                         const std::function<bool(const GridPoint&)>& occluded = {});

  double priority(const GridPoint& d) const;  // with the camera and occlusion of the last update
  // Queue members in ascending grid index (for occlusion tests and reports).
  std::vector<GridPoint> splitQueue() const;
  std::vector<GridPoint> mergeQueue() const;

 private:
  // A priority queue of diamonds by (priority, index), the highest or the lowest pair first, with
  // membership by index. A binary heap with lazy deletion: erase marks the member gone in the
  // index, and heap entries whose member is gone or whose priority is not the member's are
  // dropped when they reach the top; the heap and the index are rebuilt from the members when
  // stale entries outnumber them. So top() is the extreme (priority, index) pair of the members,
  // whatever the order of the operations: a total order, deterministic.
  class Queue {
   public:
    explicit Queue(bool highestFirst) : highestFirst_(highestFirst) {}
    void insert(std::uint64_t id, double priority);
    void erase(std::uint64_t id);
    bool contains(std::uint64_t id) const;
    bool empty() const { return size_ == 0; }
    std::size_t size() const { return size_; }
    std::pair<double, std::uint64_t> top();  // the queue must not be empty
    std::vector<std::uint64_t> ids() const;  // ascending
    // Every member's priority anew (a new camera), in one heap build.
    void reprioritise(const std::function<double(std::uint64_t)>& priorityOf);

   private:
    struct Member {
      double priority = 0.0;
      bool present = false;
    };
    bool before(const std::pair<double, std::uint64_t>& a, const std::pair<double, std::uint64_t>& b) const {
      return highestFirst_ ? a < b : b < a;  // the heap's "less": its top is the greatest
    }
    bool live(const std::pair<double, std::uint64_t>& e) const;
    void rebuild(std::vector<std::pair<double, std::uint64_t>> entries);
    // Rebuilds from the live entries when stale heap entries or absent ids outnumber the members
    // (twice over, plus 1024): memory stays proportional to the members.
    void compactIfStale();
    bool highestFirst_;
    std::size_t size_ = 0, absent_ = 0;  // members, and ids the index marks gone
    FlatU64Map<Member> index_;
    std::vector<std::pair<double, std::uint64_t>> heap_;
  };
  GridPoint pointOf(std::uint64_t id) const;
  void afterSplit(const GridPoint& q);
  void afterMerge(const GridPoint& d);
  void addIfLeaf(const GridPoint& c);

  const DiamondRanges* bounds_;
  double isovalue_;
  DiamondMesh mesh_;
  Queue split_{true}, merge_{false};
  ViewCamera camera_;
  double pixelsPerUnit_ = 0.0;  // P of the camera_, at distance 1
  std::function<bool(const GridPoint&)> occluded_;
};

}  // namespace voxref::ref
