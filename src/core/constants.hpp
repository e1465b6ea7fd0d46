#pragma once
// Physical constants with their units. Defaults that a case file may change live in the case
// structures (io/case_file.hpp), not here.

namespace flotsam {

constexpr double pi = 3.14159265358979323846;           // [-]
constexpr double gravity = 9.81;                        // [m s^-2]
constexpr double earth_rotation_rate = 7.2921e-5;       // Omega [rad s^-1], spec 1.1
constexpr double water_density_default = 1000.0;        // rho [kg m^-3], spec 2
constexpr double air_density = 1.225;                   // rho_air [kg m^-3], spec 1.1
constexpr double wind_drag_coefficient = 0.0026;        // C_w [-], the paper's r, spec 1.1
constexpr double millimetres_per_hour = 1e-3 / 3600.0;  // [m/s] in 1 mm/h (rain, infiltration)

}  // namespace flotsam
