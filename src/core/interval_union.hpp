// A union of closed intervals [a, b] of the real line, merged once and then asked whether it holds a
// value: the windows in the last coordinate within which a point may still have a nearer neighbour
// (sample --stream's and dfvn-sample-mpi's nearest-neighbour passes).
#pragma once

#include <algorithm>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace dfvn {

class IntervalUnion {
 public:
  using Interval = std::pair<double, double>;  // [first, second]

  IntervalUnion() = default;
  explicit IntervalUnion(std::vector<Interval> intervals) {
    std::sort(intervals.begin(), intervals.end());
    for (const Interval& w : intervals)
      if (!merged_.empty() && w.first <= merged_.back().second) merged_.back().second = std::max(merged_.back().second, w.second);
      else merged_.push_back(w);
  }

  // Whether some interval holds z (its ends included).
  bool contains(double z) const {
    const auto it = std::upper_bound(merged_.begin(), merged_.end(), Interval{z, std::numeric_limits<double>::infinity()});
    return it != merged_.begin() && z <= std::prev(it)->second;
  }

  // The disjoint intervals, in increasing order.
  const std::vector<Interval>& intervals() const { return merged_; }

 private:
  std::vector<Interval> merged_;
};

}  // namespace dfvn
