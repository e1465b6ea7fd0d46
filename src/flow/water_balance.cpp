#include "flow/water_balance.hpp"

#include "io/binary_archive.hpp"

namespace flotsam {

void write_water_balance(ArchiveWriter& w, const std::string& prefix, const WaterBalance& b) {
  w.write(prefix + ".balance", std::vector<double>{b.initial_volume, b.volume, b.outflow, b.source,
                                                   b.lag, b.rain, b.infiltration, b.sources});
  w.write(prefix + ".group_outflow", b.group_outflow);
  w.write(prefix + ".group_rate", b.group_rate);
}

WaterBalance read_water_balance(ArchiveReader& r, const std::string& prefix) {
  const auto sums = r.read<double>(prefix + ".balance");
  WaterBalance b;
  b.initial_volume = sums.at(0), b.volume = sums.at(1), b.outflow = sums.at(2);
  b.source = sums.at(3), b.lag = sums.at(4);
  if (sums.size() >= 7) b.rain = sums[5], b.infiltration = sums[6];
  if (sums.size() >= 8) b.sources = sums[7];
  b.group_outflow = r.read<double>(prefix + ".group_outflow");
  b.group_rate = r.read<double>(prefix + ".group_rate");
  return b;
}

}  // namespace flotsam
