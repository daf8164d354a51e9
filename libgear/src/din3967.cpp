#include <gearkit/gear/din3967.hpp>

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace gearkit::gear {

namespace {

constexpr std::array<std::string_view, 11> kDeviationSeries{"a", "ab", "b", "bc", "c", "cd", "d", "e", "f", "g", "h"};
constexpr std::array<double, 11> kUpperDiameter{10, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6300, 10000};

// DIN 3967:1978 Table 1, A_sne in um; rows: diameter ranges, columns: kDeviationSeries.
constexpr int kTable1[11][11] = {
    {-100, -85, -70, -58, -48, -40, -33, -22, -10, -5, 0},
    {-135, -110, -95, -75, -65, -54, -44, -30, -14, -7, 0},
    {-180, -150, -125, -105, -85, -70, -60, -40, -19, -9, 0},
    {-250, -200, -170, -140, -115, -95, -80, -56, -26, -12, 0},
    {-330, -280, -230, -190, -155, -130, -110, -75, -35, -17, 0},
    {-450, -370, -310, -260, -210, -175, -145, -100, -48, -22, 0},
    {-600, -500, -420, -340, -290, -240, -200, -135, -64, -30, 0},
    {-820, -680, -560, -460, -390, -320, -270, -180, -85, -41, 0},
    {-1100, -920, -760, -620, -520, -430, -360, -250, -115, -56, 0},
    {-1500, -1250, -1020, -840, -700, -580, -480, -330, -155, -75, 0},
    {-2000, -1650, -1350, -1150, -940, -780, -640, -450, -210, -100, 0},
};

// DIN 3967:1978 Table 2, T_sn in um; columns: tolerance series 21..30.
constexpr int kTable2[11][10] = {
    {3, 5, 8, 12, 20, 30, 50, 80, 130, 200},        {5, 8, 12, 20, 30, 50, 80, 130, 200, 300},
    {6, 10, 16, 25, 40, 60, 100, 160, 250, 400},    {8, 12, 20, 30, 50, 80, 130, 200, 300, 500},
    {10, 16, 25, 40, 60, 100, 160, 250, 400, 600},  {12, 20, 30, 50, 80, 130, 200, 300, 500, 800},
    {16, 25, 40, 60, 100, 160, 250, 400, 600, 1000}, {20, 30, 50, 80, 130, 200, 300, 500, 800, 1300},
    {25, 40, 60, 100, 160, 250, 400, 600, 1000, 1600}, {30, 50, 80, 130, 200, 300, 500, 800, 1300, 2000},
    {40, 60, 100, 160, 250, 400, 600, 1000, 1600, 2400},
};

// Row of the diameter range "over ... up to" that holds |d|.
int row_of(double d) {
  const double a = std::fabs(d);
  for (int i = 0; i < 11; ++i) {
    if (a <= kUpperDiameter[i]) return i;
  }
  throw std::domain_error(fmt::format("DIN 3967: tabulated up to d = 10000 mm, found {} mm", a));
}

int column_of(std::string_view series) {
  for (int i = 0; i < 11; ++i) {
    if (kDeviationSeries[i] == series) return i;
  }
  return -1;
}

}  // namespace

bool is_din3967_deviation_series(std::string_view series) { return column_of(series) >= 0; }

Din3967Designation parse_din3967(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  const std::string digits(text.substr(0, i));
  const std::string series(text.substr(i));
  if (digits.empty() || series.empty() || digits.size() > 2) {
    throw std::invalid_argument(fmt::format(
        "expected a DIN 3967 designation: tolerance series 21..30 and deviation series a..h, e.g. 27cd, found '{}'",
        text.substr(0, 60)));
  }
  const int tolerance = std::stoi(digits);
  if (tolerance < 21 || tolerance > 30) {
    throw std::invalid_argument(fmt::format("DIN 3967 has tolerance series 21..30, found {}", tolerance));
  }
  if (!is_din3967_deviation_series(series)) {
    throw std::invalid_argument(fmt::format(
        "DIN 3967 has the deviation series a, ab, b, bc, c, cd, d, e, f, g, h, found '{}'", series.substr(0, 60)));
  }
  return {tolerance, series};
}

double din3967_upper_allowance(std::string_view series, double d) {
  const int c = column_of(series);
  if (c < 0) throw std::invalid_argument(fmt::format("DIN 3967: no deviation series '{}'", series.substr(0, 60)));
  return 1e-3 * kTable1[row_of(d)][c];
}

double din3967_thickness_tolerance(int series, double d) {
  if (series < 21 || series > 30) throw std::invalid_argument(fmt::format("DIN 3967: no tolerance series {}", series));
  return 1e-3 * kTable2[row_of(d)][series - 21];
}

ThicknessAllowances din3967_allowances(const Din3967Designation& designation, double d) {
  const double A_sne = din3967_upper_allowance(designation.deviation_series, d);
  return {A_sne, A_sne - din3967_thickness_tolerance(designation.tolerance_series, d)};
}

}  // namespace gearkit::gear
