#include "core/calendar_time.hpp"

#include <fmt/format.h>

#include <cctype>

namespace flotsam {

std::string CalendarTime::text() const {
  return fmt::format("{:04d}-{:02d}-{:02d} {:02d}:{:02d}:{:02d}", year, month, day, hour, minute,
                     second);
}

namespace {

/// The n digits at text[at...], or -1.
int digits(std::string_view text, std::size_t at, int n) {
  if (at + n > text.size()) return -1;
  int value = 0;
  for (int k = 0; k < n; ++k) {
    const char c = text[at + k];
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
    value = 10 * value + (c - '0');
  }
  return value;
}

int days_in_month(int year, int month) {
  constexpr int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : days[month - 1];
}

}  // namespace

std::optional<CalendarTime> parse_calendar_time(std::string_view text) {
  if (!text.empty() && text.back() == 'Z') text.remove_suffix(1);
  if (text.size() != 10 && text.size() != 19) return std::nullopt;
  if (text[4] != '-' || text[7] != '-') return std::nullopt;
  CalendarTime t;
  t.year = digits(text, 0, 4);
  t.month = digits(text, 5, 2);
  t.day = digits(text, 8, 2);
  if (text.size() == 19) {
    if ((text[10] != ' ' && text[10] != 'T') || text[13] != ':' || text[16] != ':')
      return std::nullopt;
    t.hour = digits(text, 11, 2);
    t.minute = digits(text, 14, 2);
    t.second = digits(text, 17, 2);
  }
  if (t.year < 0 || t.month < 1 || t.month > 12 || t.day < 1 ||
      t.day > days_in_month(t.year, t.month) || t.hour < 0 || t.hour > 23 || t.minute < 0 ||
      t.minute > 59 || t.second < 0 || t.second > 59)
    return std::nullopt;
  return t;
}

}  // namespace flotsam
