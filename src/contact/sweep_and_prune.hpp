#pragma once
// Broad phase (spec 4.2): the pairs of bodies whose bounding boxes overlap, by sort-and-sweep.
//
//   order  <- body indices sorted by box.lower[axis]       (kept from the last step:
//                                                           insertion sort, nearly linear)
//   for k in order:                                          the sweep line reaches box k
//     for m after k while lower[axis][m] <= upper[axis][k]:  boxes open on the sweep axis
//       if the boxes overlap on the other axis: emit (k, m)
//
// The sweep meets only the boxes of k's bands: strips across the other axis about two boxes wide,
// in which each box is listed in the order's order (a jam across a wide river then does not test
// every log of its row). A pair that shares two bands is emitted in the one where its overlap
// starts, and box k's partners in the order's order, so the pairs are those of one sweep, in its
// order.
//
// The sweep axis is the one along which the boxes' centres spread most (a jam in a river is long
// along the flow); when it changes, the order is sorted afresh. brute_force_pairs() tests every
// pair and returns the same set: tests and benchmarks compare the two.
#include <utility>
#include <vector>

#include "contact/boundary_segments.hpp"

namespace flotsam {

using BodyPair = std::pair<int, int>;  // (i, j), i < j: body indices

class SweepAndPrune {
 public:
  /// Pairs (i < j) of boxes that overlap (closed boxes: touching counts), for the boxes whose
  /// `active` flag is set. Appends to `pairs` after clearing it; order unspecified.
  void find_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                  std::vector<BodyPair>& pairs);
  /// The same with `listed`, the indices of the active boxes in ascending order: costs the
  /// listed boxes and the last call's, not all of them (a small contact group in a large set).
  void find_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                  const std::vector<int>& listed, std::vector<BodyPair>& pairs);

  int axis() const { return axis_; }
  /// The order kept between steps and its axis: a checkpoint keeps them so that a restarted run
  /// finds its pairs in the same order (and so solves its contacts in the same order).
  const std::vector<int>& order() const { return order_; }
  void restore(std::vector<int> order, int axis) {
    order_ = std::move(order);
    axis_ = axis;
    in_order_.clear();  // marked afresh below
    for (const int i : order_) {
      if (i >= static_cast<int>(in_order_.size()))
        in_order_.resize(static_cast<std::size_t>(i) + 1, 0);
      in_order_[i] = 1;
    }
  }
  long swaps_last_step() const { return swaps_; }  // insertion-sort moves [-], for profiling

 private:
  std::vector<int> order_;      // active body indices sorted by lower bound on the sweep axis
  std::vector<char> in_order_;  // 1 for the indices in order_
  int axis_ = 0;                // 0: x, 1: y
  long swaps_ = 0;
  void list_in_bands();
  int band_of(double other) const;  // the band of a coordinate along the other axis
  void sweep_box(std::size_t k, std::vector<BodyPair>& found, std::vector<int>& partners) const;

  // Sorted copies of the bounds (k: the place in order_).
  std::vector<double> lower_, upper_, other_lower_, other_upper_;
  // Bands: band b's entries are band_start_[b] to band_start_[b + 1] - 1, each an order place
  // (member_) with its bounds, contiguous for the sweep; box k's entries in its bands
  // first_band_[k], first_band_[k] + 1, ... are at position_[entry_start_[k]],
  // position_[entry_start_[k] + 1], ...
  double band_low_ = 0.0, band_scale_ = 0.0;  // [m], [1/m]: band = (other - low) * scale
  int band_count_ = 1;
  std::vector<int> band_start_, fill_, first_band_, entry_start_, member_, position_;
  std::vector<double> band_lower_, band_other_lower_, band_other_upper_;
  struct Run {  // a thread's run of the sweep
    std::vector<BodyPair> pairs;
    std::vector<int> partners;  // of one box
  };
  std::vector<Run> runs_;
};

/// Every overlapping pair (i < j) of active boxes by testing all pairs: O(N^2), the reference.
void brute_force_pairs(const std::vector<Aabb>& boxes, const std::vector<char>& active,
                       std::vector<BodyPair>& pairs);

}  // namespace flotsam
