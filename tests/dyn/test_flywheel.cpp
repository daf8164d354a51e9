// Tests of gearkit/dyn/flywheel.hpp against OTM 2015 problem 4 (seed 000_bc94d104a9983772.txt):
// motor 100 kW at 2950 rpm, gear z2 = 20 / z3 = 50, triangular resisting torque on the load
// shaft (zero to 90 deg, peak at 180 deg, zero at 360 deg), delta = 0.5 %, machine 0.1 kg*m^2.
#include <gearkit/dyn/flywheel.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace gearkit::dyn;
constexpr double pi = std::numbers::pi;

namespace {

struct Otm4 {
  double omega_motor = 2950 * 2 * pi / 60;
  double omega_load = omega_motor * 20.0 / 50.0;
  double motor_torque = 100e3 / omega_motor;
  double drive_at_load = motor_torque * 50.0 / 20.0;
  PiecewiseLinear shape{{0, pi / 2, pi, 2 * pi}, {0, 0, 1, 0}, true};
};

}  // namespace

TEST(Flywheel, Otm2015Problem4) {
  const Otm4 p;
  // Printed: omega_4 = 123.569 rad/s, M_m = 323.705 N*m, M_m4 = 809.262 N*m.
  EXPECT_NEAR(p.omega_load, 123.569, 0.0005);
  EXPECT_NEAR(p.motor_torque, 323.705, 0.0005);
  EXPECT_NEAR(p.drive_at_load, 809.262, 0.0005);

  const PiecewiseLinear drive = PiecewiseLinear::constant(p.drive_at_load, 0, 2 * pi);
  const double peak = balance_scale(drive, p.shape);
  EXPECT_NEAR(peak, 2.158e3, 0.5);  // printed M_r_max = 2.158e3 N*m (= 8/3 M_m4)

  const CycleEnergy c = analyse_cycle(drive, p.shape.scaled(peak));
  EXPECT_NEAR(c.theta_at_energy_max, 2.16, 0.005);    // printed theta_max = 2.16 rad
  EXPECT_NEAR(c.theta_at_energy_min, 5.105, 0.0005);  // printed theta_min = 5.105 rad
  EXPECT_NEAR(c.energy_excursion, 1.986e3, 0.5);      // printed W_AB = 1.986e3 J
  EXPECT_NEAR(c.drive_energy, c.resist_energy, 1e-9 * c.drive_energy);
  EXPECT_NEAR(c.mean_drive_torque, p.drive_at_load, 1e-9);

  const FlywheelSizing s = size_flywheel(c.energy_excursion, p.omega_load, 0.005, 0.1);
  EXPECT_NEAR(s.omega_max, 123.878, 0.0005);        // printed
  EXPECT_NEAR(s.omega_min, 123.26, 0.005);          // printed 123.26
  EXPECT_NEAR(s.inertia_total, 26.016, 0.0005);     // printed I_tot = 26.016 kg*m^2
  EXPECT_NEAR(s.inertia_flywheel, 25.916, 0.0005);  // printed I_v = 25.916 kg*m^2
  EXPECT_TRUE(s.flywheel_needed);
}

TEST(Flywheel, ClosedFormAnglesOfTheTriangle) {
  // Similar triangles (seed's own derivation): theta_max = pi/2 + 3/8 (pi - pi/2),
  // theta_min = 2 pi - 3/8 (2 pi - pi), W = (M_r - M_m)(theta_min - theta_max) / 2.
  const Otm4 p;
  const PiecewiseLinear drive = PiecewiseLinear::constant(p.drive_at_load, 0, 2 * pi);
  const double peak = p.drive_at_load * 8 / 3;
  const CycleEnergy c = analyse_cycle(drive, p.shape.scaled(peak));
  const double tmax = pi / 2 + 3.0 / 8 * (pi / 2), tmin = 2 * pi - 3.0 / 8 * pi;
  EXPECT_NEAR(c.theta_at_energy_max, tmax, 1e-12);
  EXPECT_NEAR(c.theta_at_energy_min, tmin, 1e-12);
  EXPECT_NEAR(c.energy_excursion, 0.5 * (peak - p.drive_at_load) * (tmin - tmax), 1e-9);
  // Two lobes of equal and opposite area; the surplus lobe wraps past the cycle end.
  ASSERT_EQ(c.lobes.size(), 2u);
  EXPECT_NEAR(c.lobes[0].theta_start, tmax, 1e-12);
  EXPECT_NEAR(c.lobes[0].theta_end, tmin, 1e-12);
  EXPECT_NEAR(c.lobes[0].energy, -c.energy_excursion, 1e-9);
  EXPECT_NEAR(c.lobes[1].theta_end, tmax + 2 * pi, 1e-12);
  EXPECT_NEAR(c.lobes[1].energy, c.energy_excursion, 1e-9);
  EXPECT_NEAR(energy_at(drive, p.shape.scaled(peak), tmax), c.energy_max, 1e-9);
}

TEST(Flywheel, LargestExcursionSpansSeveralLobes) {
  // Net torque +1, -1, +2, -2 over four quarters (steps): E = 0, pi/2, 0, pi, 0 at the quarter
  // ends, so the largest excursion is pi (from theta = 0 to 3 pi / 2), not one lobe's area.
  const PiecewiseLinear drive = PiecewiseLinear::constant(0, 0, 2 * pi);
  const PiecewiseLinear resist({0, pi / 2, pi / 2, pi, pi, 1.5 * pi, 1.5 * pi, 2 * pi, 2 * pi},
                               {-1, -1, 1, 1, -2, -2, 2, 2, -1}, true);
  const CycleEnergy c = analyse_cycle(drive, resist);
  EXPECT_NEAR(c.energy_max, pi, 1e-12);
  EXPECT_NEAR(c.theta_at_energy_max, 1.5 * pi, 1e-12);
  EXPECT_NEAR(c.energy_min, 0, 1e-12);
  EXPECT_NEAR(c.energy_excursion, pi, 1e-12);
  ASSERT_EQ(c.lobes.size(), 4u);
  EXPECT_NEAR(c.lobes[2].energy, pi, 1e-12);
}

TEST(Flywheel, UnbalancedCycleIsRejected) {
  const PiecewiseLinear drive = PiecewiseLinear::constant(1000, 0, 2 * pi);
  const PiecewiseLinear resist = PiecewiseLinear::constant(900, 0, 2 * pi);
  try {
    analyse_cycle(drive, resist);
    FAIL() << "an unbalanced cycle is not steady";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not steady"), std::string::npos) << e.what();
  }
  EXPECT_THROW(analyse_cycle(PiecewiseLinear({0, 2 * pi}, {1, 2}, false), resist), std::invalid_argument);
}

TEST(Flywheel, SizingChecksItsInputs) {
  EXPECT_THROW(size_flywheel(100, 0, 0.01, 1), std::invalid_argument);
  EXPECT_THROW(size_flywheel(100, 10, 0, 1), std::invalid_argument);
  EXPECT_THROW(size_flywheel(100, 10, 2.5, 1), std::invalid_argument);
  EXPECT_THROW(size_flywheel(-1, 10, 0.01, 1), std::invalid_argument);
  EXPECT_THROW(size_flywheel(100, 10, 0.01, -1), std::invalid_argument);
  EXPECT_THROW(size_flywheel(NAN, 10, 0.01, 1), std::invalid_argument);
  // A machine heavy enough needs no flywheel: E / (I w^2) = 100 / (10 * 100) = 0.1 < 0.2.
  const FlywheelSizing s = size_flywheel(100, 10, 0.2, 10);
  EXPECT_FALSE(s.flywheel_needed);
  EXPECT_EQ(s.inertia_flywheel, 0);
  EXPECT_NEAR(s.fluctuation_without_flywheel, 0.1, 1e-15);
  EXPECT_NEAR(fluctuation_for_inertia(100, 10, 5), 0.2, 1e-15);
  EXPECT_THROW(fluctuation_for_inertia(100, 10, 0), std::invalid_argument);
}
