#pragma once
// Flood hazard to people and vehicles from a cell's depth d [m] and speed v [m/s]
// (docs/model.md "Flood hazard", (M-H1)-(M-H4)). The flood envelopes (flood_envelope.hpp) keep
// the largest of each over the run, evaluated at every sub-step from that sub-step's d and v:
// never from the largest depth and the largest speed, which seldom occur together (AIDR 2017,
// Guideline 7-3, Fig. 4).

namespace flotsam {

/// The debris factor DF of FD2321 (Defra/Environment Agency 2006, its table of debris factors by
/// depth and land use) where flotsam's own bodies are in the cell (`debris`): 0 up to 0.25 m deep,
/// 1 deeper (the table's value for where debris is present at any speed, its "urban" column); 0
/// where no body is. (M-H2)
double debris_factor(double d, bool debris);

/// The UK hazard rating HR = d (v + 0.5) + DF (FD2321) [-]. (M-H1)
double hazard_rating(double d, double v, double debris_factor);

/// FD2321's four classes of HR: 1 low (HR < 0.75, "caution"), 2 moderate (0.75 <= HR <= 1.25,
/// danger for some), 3 significant (1.25 < HR <= 2.0, danger for most), 4 extreme (HR > 2.0,
/// danger for all). (M-H1)
int hazard_rating_class(double hr);

/// The Australian hazard classes H1-H6 (AIDR Guideline 7-3, 2017, Table 6; ARR 2019 Book 6
/// ch. 7): the first class, from H1 up, whose limits on d v, d and v the cell meets (each limit
/// inclusive); 6 beyond H5's. (M-H3)
int australian_hazard_class(double d, double v);

/// Vehicles that lose stability (Shand et al. 2011, ARR Project 10 Stage 2 report P10/S2/020,
/// Table 3): 0 none, 1 small passenger cars, 2 large passenger cars as well, 3 large 4WDs as
/// well. A vehicle is stable while d <= its still-water depth limit, v <= 3 m/s and d v <= its
/// limit. (M-H4)
int unstable_vehicle_class(double d, double v);

}  // namespace flotsam
