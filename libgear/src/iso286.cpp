#include <gearkit/gear/iso286.hpp>

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace gearkit::gear {

namespace {

// ISO 286-1:2010 Table 1, upper limits of the size ranges (mm) and IT5..IT11 in um; 0 where not
// tabulated here (IT5 above 500 mm).
constexpr std::array<double, 21> kUpper{3,   6,   10,  18,   30,   50,   80,   120,  180,  250, 315,
                                        400, 500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150};
constexpr int kRows = 21;
constexpr double kIt[7][kRows] = {
    {4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27, 0, 0, 0, 0, 0, 0, 0, 0},                             // IT5
    {6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40, 44, 50, 56, 66, 78, 92, 110, 135},                 // IT6
    {10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63, 70, 80, 90, 105, 125, 150, 175, 210},           // IT7
    {14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97, 110, 125, 140, 165, 195, 230, 280, 330},        // IT8
    {25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155, 175, 200, 230, 260, 310, 370, 440, 540},   // IT9
    {40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250, 280, 320, 360, 420, 500, 600, 700, 860},  // IT10
    {60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400, 440, 500, 560, 660, 780, 920, 1100, 1350},  // IT11
};

}  // namespace

double standard_tolerance(int it_grade, double size) {
  if (!(size > 0.0 && size <= kMaxIso286Size)) {
    throw std::domain_error(fmt::format("ISO 286: expected a size in (0, 3150] mm, found {} mm", size));
  }
  int row = 0;
  while (size > kUpper[row]) ++row;
  if (it_grade < kMinItGrade || it_grade > kMaxItGrade || kIt[it_grade - kMinItGrade][row] == 0.0) {
    throw std::domain_error(fmt::format("ISO 286: IT{} is not tabulated for {} mm (IT5..IT11 up to 500 mm, "
                                        "IT6..IT11 up to 3150 mm)", it_grade, size));
  }
  return kIt[it_grade - kMinItGrade][row];
}

double js_limit_deviation(int it_grade, double size) { return 0.5e-3 * standard_tolerance(it_grade, size); }

}  // namespace gearkit::gear
