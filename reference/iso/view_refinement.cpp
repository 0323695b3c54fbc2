#include "reference/iso/view_refinement.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace voxref::ref {

bool ViewRefinement::Queue::live(const std::pair<double, std::uint64_t>& e) const {
  const Member* m = index_.find(e.second);
  return m && m->present && m->priority == e.first;
}

void ViewRefinement::Queue::insert(std::uint64_t id, double priority) {
  auto [m, added] = index_.try_emplace(id, Member{priority, true});
  if (added) {
    ++size_;
  } else if (m.present) {
    if (m.priority == priority) return;  // there already, at this priority
    m.priority = priority;               // its older heap entry is stale now
  } else {
    m = Member{priority, true};
    --absent_;
    ++size_;
  }
  heap_.emplace_back(priority, id);
  std::push_heap(heap_.begin(), heap_.end(), [this](const auto& a, const auto& b) { return before(a, b); });
  compactIfStale();
}

void ViewRefinement::Queue::compactIfStale() {
  if (heap_.size() <= 2 * size_ + 1024 && absent_ <= 2 * size_ + 1024) return;
  std::vector<std::pair<double, std::uint64_t>> entries;
  for (const auto& e : heap_)
    if (live(e)) entries.push_back(e);
  rebuild(std::move(entries));
}

void ViewRefinement::Queue::erase(std::uint64_t id) {
  Member* m = index_.find(id);
  if (!m || !m->present) return;
  m->present = false;
  --size_;
  ++absent_;
  compactIfStale();
}

bool ViewRefinement::Queue::contains(std::uint64_t id) const {
  const Member* m = index_.find(id);
  return m && m->present;
}

std::pair<double, std::uint64_t> ViewRefinement::Queue::top() {
  const auto cmp = [this](const auto& a, const auto& b) { return before(a, b); };
  while (!live(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), cmp);
    heap_.pop_back();
  }
  return heap_.front();
}

std::vector<std::uint64_t> ViewRefinement::Queue::ids() const {
  std::vector<std::uint64_t> ids;
  ids.reserve(size_);
  for (const auto& e : heap_)
    if (live(e)) ids.push_back(e.second);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());  // a member re-inserted at its old priority
  return ids;
}

void ViewRefinement::Queue::rebuild(std::vector<std::pair<double, std::uint64_t>> entries) {
  const auto byId = [](const auto& a, const auto& b) { return a.second < b.second; };
  if (!std::is_sorted(entries.begin(), entries.end(), byId)) std::sort(entries.begin(), entries.end(), byId);
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  index_.reset(entries.size());
  for (const auto& e : entries) index_.try_emplace(e.second, Member{e.first, true});
  size_ = entries.size();
  absent_ = 0;
  heap_ = std::move(entries);
  std::make_heap(heap_.begin(), heap_.end(), [this](const auto& a, const auto& b) { return before(a, b); });
}

void ViewRefinement::Queue::reprioritise(const std::function<double(std::uint64_t)>& priorityOf) {
  std::vector<std::pair<double, std::uint64_t>> entries;
  for (const std::uint64_t id : ids()) entries.emplace_back(priorityOf(id), id);
  rebuild(std::move(entries));
}

ViewRefinement::ViewRefinement(const DiamondRanges& bounds, double isovalue)
    : bounds_(&bounds), isovalue_(isovalue), mesh_(bounds.lebGrid()) {
  if (bounds.lebGrid().k >= 1) {
    const int h = bounds.lebGrid().side() / 2;
    split_.insert(bounds.lebGrid().linearIndex({h, h, h}), 0.0);  // the root diamond
  }
}

GridPoint ViewRefinement::pointOf(std::uint64_t id) const { return bounds_->lebGrid().pointAt(id); }

double ViewRefinement::priority(const GridPoint& d) const {
  if (!bounds_->mayContain(d, isovalue_)) return 0.0;
  if (occluded_ && occluded_(d)) return 0.0;
  const GridBox box = diamondBox(bounds_->lebGrid(), d);
  const glm::dvec3 lo(box.lo[0], box.lo[1], box.lo[2]), hi(box.hi[0], box.hi[1], box.hi[2]);
  const double radius = 0.5 * glm::length(hi - lo);
  const double distance = glm::length(glm::dvec3(d[0], d[1], d[2]) - camera_.eye);
  return bounds_->errorOf(d) * pixelsPerUnit_ / std::max(distance, radius);
}

void ViewRefinement::addIfLeaf(const GridPoint& c) {
  if (mesh_.isSplit(c)) return;
  for (const GridPoint& p : diamondParents(bounds_->lebGrid(), c))
    if (!mesh_.isSplit(p)) return;
  split_.insert(bounds_->lebGrid().linearIndex(c), priority(c));
}

void ViewRefinement::afterSplit(const GridPoint& q) {
  const LebGrid& g = bounds_->lebGrid();
  split_.erase(g.linearIndex(q));
  for (const GridPoint& p : diamondParents(g, q)) merge_.erase(g.linearIndex(p));
  merge_.insert(g.linearIndex(q), priority(q));
  for (const GridPoint& c : diamondChildren(g, q)) addIfLeaf(c);
}

void ViewRefinement::afterMerge(const GridPoint& d) {
  const LebGrid& g = bounds_->lebGrid();
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
  pixelsPerUnit_ = camera.height / (2.0 * std::tan(camera.fovYDegrees * 3.14159265358979323846 / 360.0));
  occluded_ = occluded;
  // New camera: every priority changes.
  for (Queue* q : {&split_, &merge_}) q->reprioritise([&](std::uint64_t id) { return priority(pointOf(id)); });
  RefinementStats stats;
  while (!split_.empty() && split_.top().first > budget.threshold) {
    if (stats.splits >= budget.maxSplits) {
      stats.budgetExhausted = true;
      break;
    }
    for (const GridPoint& q : mesh_.split(pointOf(split_.top().second))) {
      afterSplit(q);
      ++stats.splits;
    }
  }
  while (!merge_.empty() && merge_.top().first <= budget.threshold && stats.merges < budget.maxMerges) {
    const GridPoint d = pointOf(merge_.top().second);
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
