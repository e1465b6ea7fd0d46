// Calendar times (core/calendar_time.hpp): the forms read, and days that do not exist refused.
#include "core/calendar_time.hpp"

#include <gtest/gtest.h>

namespace flotsam {
namespace {

TEST(CalendarTime, ReadsTheDateAndTimeFormsAndWritesTheCfForm) {
  EXPECT_EQ(parse_calendar_time("2024-06-01 06:30:05")->text(), "2024-06-01 06:30:05");
  EXPECT_EQ(parse_calendar_time("2024-06-01T06:30:05Z")->text(), "2024-06-01 06:30:05");
  EXPECT_EQ(parse_calendar_time("2024-02-29")->text(), "2024-02-29 00:00:00");  // a leap year
  EXPECT_EQ(CalendarTime{}.text(), "1970-01-01 00:00:00");
}

TEST(CalendarTime, RefusesTimesThatAreNotThere) {
  for (const char* bad :
       {"2023-02-29", "2000-13-01", "2000-04-31", "2000-01-01 24:00:00", "2000-01-01 10:60:00",
        "2000-1-1", "01/06/2024", "2000-01-01 10:00", "", "2000-01-01x10:00:00"})
    EXPECT_FALSE(parse_calendar_time(bad).has_value()) << bad;
  EXPECT_TRUE(parse_calendar_time("1900-02-28").has_value());
  EXPECT_FALSE(parse_calendar_time("1900-02-29").has_value());  // not a leap year
  EXPECT_TRUE(parse_calendar_time("2000-02-29").has_value());   // a leap year
}

}  // namespace
}  // namespace flotsam
