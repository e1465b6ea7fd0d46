#include "flow/hazard.hpp"

#include <array>

namespace flotsam {

namespace {

/// Limits a cell must meet to be in a class: all three, each inclusive.
struct Limits {
  double dv;     // [m^2/s] depth x velocity
  double depth;  // [m]
  double speed;  // [m/s]
};

bool within(const Limits& l, double d, double v) {
  return d * v <= l.dv && d <= l.depth && v <= l.speed;
}

// AIDR Guideline 7-3 (2017), Table 6: H1 ... H5; beyond H5 is H6.
constexpr std::array<Limits, 5> australian_classes = {{
    {0.3, 0.3, 2.0},  // H1 generally safe for people, vehicles and buildings
    {0.6, 0.5, 2.0},  // H2 unsafe for small vehicles
    {0.6, 1.2, 2.0},  // H3 unsafe for vehicles, children and the elderly
    {1.0, 2.0, 2.0},  // H4 unsafe for vehicles and people
    {4.0, 4.0, 4.0},  // H5 as H4; all buildings vulnerable to structural damage
}};

// Shand et al. (2011), Table 3: the limits of stability, from the least stable vehicle up.
constexpr std::array<Limits, 3> vehicles = {{
    {0.30, 0.3, 3.0},  // small passenger car: < 4.3 m long, < 1,250 kg, clearance < 0.12 m
    {0.45, 0.4, 3.0},  // large passenger car: > 4.3 m, > 1,250 kg, clearance > 0.12 m
    {0.60, 0.5, 3.0},  // large 4WD: > 4.5 m, > 2,000 kg, clearance > 0.22 m
}};

}  // namespace

double debris_factor(double d, bool debris) {
  constexpr double shallow = 0.25;  // [m] FD2321: no debris factor up to this depth
  return debris && d > shallow ? 1.0 : 0.0;
}

double hazard_rating(double d, double v, double debris_factor) {
  return d * (v + 0.5) + debris_factor;  // (M-H1), 0.5 m/s
}

int hazard_rating_class(double hr) {
  return hr < 0.75 ? 1 : hr <= 1.25 ? 2 : hr <= 2.0 ? 3 : 4;
}

int australian_hazard_class(double d, double v) {
  for (int k = 0; k < static_cast<int>(australian_classes.size()); ++k)
    if (within(australian_classes[k], d, v)) return k + 1;
  return 6;
}

int unstable_vehicle_class(double d, double v) {
  int unstable = 0;
  for (const Limits& l : vehicles)
    if (!within(l, d, v)) ++unstable;
  return unstable;
}

}  // namespace flotsam
