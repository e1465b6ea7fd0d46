#pragma once
// A calendar time in UTC, "YYYY-MM-DD hh:mm:ss": the time origin of a run's results (time.origin,
// the calendar time of t = 0), as the time axes of UGRID NetCDF files ("seconds since ...") and
// the date-time fields of GeoPackage layers want it.
#include <optional>
#include <string>
#include <string_view>

namespace flotsam {

struct CalendarTime {
  int year = 1970, month = 1, day = 1, hour = 0, minute = 0, second = 0;

  /// "YYYY-MM-DD hh:mm:ss" (the form CF's "seconds since" units and QGIS read).
  std::string text() const;
};

/// Reads "YYYY-MM-DD", "YYYY-MM-DD hh:mm:ss" or "YYYY-MM-DDThh:mm:ss" (an optional trailing
/// "Z"); nothing when the text is not such a time or names no such day (2023-02-29).
std::optional<CalendarTime> parse_calendar_time(std::string_view text);

}  // namespace flotsam
