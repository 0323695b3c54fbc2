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
#include <map>
#include <set>
#include <unordered_map>
#include <vector>

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
  ViewRefinement(const DiamondBounds& bounds, double isovalue);

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
  // An ordered set of diamonds by (priority, index) with membership by index.
  class Queue {
   public:
    void insert(std::uint64_t id, double priority);
    void erase(std::uint64_t id);
    bool contains(std::uint64_t id) const { return priority_.count(id) != 0; }
    bool empty() const { return order_.empty(); }
    std::size_t size() const { return order_.size(); }
    std::pair<double, std::uint64_t> highest() const { return *order_.rbegin(); }
    std::pair<double, std::uint64_t> lowest() const { return *order_.begin(); }
    std::vector<std::uint64_t> ids() const;
    void clear();

   private:
    std::set<std::pair<double, std::uint64_t>> order_;
    std::unordered_map<std::uint64_t, double> priority_;
  };
  GridPoint pointOf(std::uint64_t id) const;
  void afterSplit(const GridPoint& q);
  void afterMerge(const GridPoint& d);
  void addIfLeaf(const GridPoint& c);

  const DiamondBounds* bounds_;
  double isovalue_;
  DiamondMesh mesh_;
  Queue split_, merge_;
  ViewCamera camera_;
  std::function<bool(const GridPoint&)> occluded_;
};

}  // namespace voxref::ref
