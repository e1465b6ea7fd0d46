#include "contact/contact_colours.hpp"

#include <algorithm>
#include <bit>
#include <numeric>

namespace flotsam {

void ContactColours::assign(std::span<const ContactConstraint> contacts,
                            const std::vector<char>& movable) {
  ends_.resize(contacts.size());
  for (std::size_t m = 0; m < contacts.size(); ++m) ends_[m] = {contacts[m].a, contacts[m].b};
  assign(ends_, movable);
}

void ContactColours::assign(std::span<const BodyPair> ends, const std::vector<char>& movable) {
  used_.assign(movable.size(), 0);
  colour_of_.resize(ends.size());
  int colours = 0;
  for (std::size_t m = 0; m < ends.size(); ++m) {
    const auto [ca, cb] = ends[m];
    const bool a = movable[ca] != 0, b = cb >= 0 && movable[cb] != 0;
    const std::uint64_t taken = (a ? used_[ca] : 0) | (b ? used_[cb] : 0);
    const int colour = std::countr_one(taken);  // max_colours when all are taken: the overflow
    colour_of_[m] = colour;
    if (colour < max_colours) {
      const std::uint64_t bit = std::uint64_t{1} << colour;
      if (a) used_[ca] |= bit;
      if (b) used_[cb] |= bit;
      colours = std::max(colours, colour + 1);
    }
  }
  // Counting sort by colour (stable), the overflow last.
  start_.assign(static_cast<std::size_t>(colours + 2), 0);
  for (int& colour : colour_of_) {
    if (colour == max_colours) colour = colours;
    ++start_[colour + 1];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  order_.resize(ends.size());
  std::vector<int> next(start_.begin(), start_.end() - 1);
  for (std::size_t m = 0; m < ends.size(); ++m) order_[next[colour_of_[m]]++] = static_cast<int>(m);
}

}  // namespace flotsam
