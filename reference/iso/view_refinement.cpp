#include "reference/iso/view_refinement.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace voxref::ref {

void ViewRefinement::Queue::insert(std::uint64_t id, double priority) {
  erase(id);
  order_.emplace(priority, id);
  priority_.emplace(id, priority);
}

void ViewRefinement::Queue::erase(std::uint64_t id) {
  const auto it = priority_.find(id);
  if (it == priority_.end()) return;
  order_.erase({it->second, id});
  priority_.erase(it);
}

std::vector<std::uint64_t> ViewRefinement::Queue::ids() const {
  std::vector<std::uint64_t> ids;
  ids.reserve(priority_.size());
  for (const auto& [id, p] : priority_) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

void ViewRefinement::Queue::clear() {
  order_.clear();
  priority_.clear();
}

ViewRefinement::ViewRefinement(const DiamondBounds& bounds, double isovalue)
    : bounds_(&bounds), isovalue_(isovalue), mesh_(bounds.grid) {
  if (bounds.grid.k >= 1) {
    const int h = bounds.grid.side() / 2;
    split_.insert(bounds.grid.linearIndex({h, h, h}), 0.0);  // the root diamond
  }
}

GridPoint ViewRefinement::pointOf(std::uint64_t id) const { return bounds_->grid.pointAt(id); }

double ViewRefinement::priority(const GridPoint& d) const {
  if (!bounds_->mayContain(d, isovalue_)) return 0.0;
  if (occluded_ && occluded_(d)) return 0.0;
  const GridBox box = diamondBox(bounds_->grid, d);
  const glm::dvec3 lo(box.lo[0], box.lo[1], box.lo[2]), hi(box.hi[0], box.hi[1], box.hi[2]);
  const double radius = 0.5 * glm::length(hi - lo);
  const double distance = glm::length(glm::dvec3(d[0], d[1], d[2]) - camera_.eye);
  const double pixelsPerUnit = camera_.height / (2.0 * std::tan(camera_.fovYDegrees * 3.14159265358979323846 / 360.0));
  return bounds_->errorOf(d) * pixelsPerUnit / std::max(distance, radius);
}

void ViewRefinement::addIfLeaf(const GridPoint& c) {
  if (mesh_.isSplit(c)) return;
  for (const GridPoint& p : diamondParents(bounds_->grid, c))
    if (!mesh_.isSplit(p)) return;
  split_.insert(bounds_->grid.linearIndex(c), priority(c));
}

void ViewRefinement::afterSplit(const GridPoint& q) {
  const LebGrid& g = bounds_->grid;
  split_.erase(g.linearIndex(q));
  for (const GridPoint& p : diamondParents(g, q)) merge_.erase(g.linearIndex(p));
  merge_.insert(g.linearIndex(q), priority(q));
  for (const GridPoint& c : diamondChildren(g, q)) addIfLeaf(c);
}

void ViewRefinement::afterMerge(const GridPoint& d) {
  const LebGrid& g = bounds_->grid;
  merge_.erase(g.linearIndex(d));
  for (const GridPoint& c : diamondChildren(g, d)) split_.erase(g.linearIndex(c));
  split_.insert(g.linearIndex(d), priority(d));
  for (const GridPoint& p : diamondParents(g, d))
    if (mesh_.canMerge(p)) merge_.insert(g.linearIndex(p), priority(p));
}

RefinementStats ViewRefinement::update(const ViewCamera& camera, const RefinementBudget& budget,
                                       const std::function<bool(const GridPoint&)>& occluded) {
  cameraBasis(camera);  // validates
  camera_ = camera;
  occluded_ = occluded;
  // New camera: every priority changes.
  for (Queue* q : {&split_, &merge_}) {
    const std::vector<std::uint64_t> ids = q->ids();
    q->clear();
    for (std::uint64_t id : ids) q->insert(id, priority(pointOf(id)));
  }
  RefinementStats stats;
  while (!split_.empty() && split_.highest().first > budget.threshold) {
    if (stats.splits >= budget.maxSplits) {
      stats.budgetExhausted = true;
      break;
    }
    for (const GridPoint& q : mesh_.split(pointOf(split_.highest().second))) {
      afterSplit(q);
      ++stats.splits;
    }
  }
  while (!merge_.empty() && merge_.lowest().first <= budget.threshold && stats.merges < budget.maxMerges) {
    const GridPoint d = pointOf(merge_.lowest().second);
    mesh_.merge(d);
    afterMerge(d);
    ++stats.merges;
  }
  stats.splitQueue = split_.size();
  stats.mergeQueue = merge_.size();
  return stats;
}

std::vector<GridPoint> ViewRefinement::splitQueue() const {
  std::vector<GridPoint> out;
  for (std::uint64_t id : split_.ids()) out.push_back(pointOf(id));
  return out;
}

std::vector<GridPoint> ViewRefinement::mergeQueue() const {
  std::vector<GridPoint> out;
  for (std::uint64_t id : merge_.ids()) out.push_back(pointOf(id));
  return out;
}

}  // namespace voxref::ref
