#pragma once
// For the tests of bridges on straight channels: a bridge whose axis crosses the channel
// y in [0, width] at x, from 1 m beyond its right bank (y = 0: the flow runs along +x) to 1 m
// beyond its left bank, and a deck without railing.
#include <optional>
#include <string>

#include "bridges/bridge_config.hpp"

namespace flotsam::test {

inline DeckConfig plain_deck(double soffit, double top, double width) {
  return {
      .soffit = soffit, .top = top, .width = width, .railing_height = 0.0, .railing_open = true};
}

inline BridgeConfig bridge_across(const std::string& name, double x, double width,
                                  std::optional<DeckConfig> deck = std::nullopt,
                                  double backwater_distance = 0.0) {
  return {.name = name,
          .start = Vec2(x, -1.0),
          .end = Vec2(x, width + 1.0),
          .pier_groups = {},
          .deck = deck,
          .backwater_distance = backwater_distance,
          .origin = "test"};
}

}  // namespace flotsam::test
