#pragma once
// Steady cyclic operation and flywheel sizing on one shaft (the "reduction shaft").
//
// Over one cycle of angle the driving torque T_d(theta) and the resisting torque T_r(theta),
// both reduced to the shaft, do equal work. In between, the kinetic energy rises and falls by
//   E(theta) = integral from theta_0 to theta of (T_d - T_r) dtheta,
// so the speed is highest where E is highest (a crossing from T_d > T_r to T_d < T_r) and
// lowest where E is lowest. With the total inertia I reduced to the shaft held constant,
//   E_max - E_min = 1/2 I (omega_max^2 - omega_min^2) = I * delta * omega_m^2,
// where omega_m = (omega_max + omega_min) / 2 and delta = (omega_max - omega_min) / omega_m is
// the coefficient of speed fluctuation (grado de irregularidad). The last equality is exact for
// that definition of omega_m.
//
// SI units: rad, N*m, J, rad/s, kg*m^2.
#include <gearkit/dyn/curve.hpp>

#include <vector>

namespace gearkit::dyn {

/// A stretch of the cycle where the driving torque stays above (energy > 0, the machine speeds
/// up) or below (energy < 0) the resisting torque: one shaded area of a textbook torque diagram.
struct EnergyLobe {
  double theta_start = 0;  ///< rad
  double theta_end = 0;    ///< rad; may pass the cycle end for the lobe that wraps around
  double energy = 0;       ///< J, integral of (T_d - T_r) over the lobe
};

struct CycleEnergy {
  double theta_start = 0, period = 0;  ///< rad
  double drive_energy = 0;             ///< J per cycle, integral of T_d
  double resist_energy = 0;            ///< J per cycle, integral of T_r
  double mean_drive_torque = 0;        ///< N*m
  double mean_resist_torque = 0;       ///< N*m
  double energy_max = 0, energy_min = 0;            ///< J, extremes of E(theta), E(theta_start) = 0
  double theta_at_energy_max = 0;                   ///< rad, where the speed is highest
  double theta_at_energy_min = 0;                   ///< rad, where the speed is lowest
  double energy_excursion = 0;                      ///< J, E_max - E_min
  std::vector<EnergyLobe> lobes;                    ///< in order from theta_start
};

/// Energy analysis of one steady cycle. Both curves must be periodic over the same range.
/// Exact for piecewise-linear curves (extremes at the crossings found in closed form).
/// Among equal extremes the first one in the cycle is reported.
/// @throws std::invalid_argument if a curve is not periodic, the ranges differ, or the cycle is
///         not steady: |drive_energy - resist_energy| above `balance_tolerance` times the larger
///         of the two (the message gives both energies and suggests balancing).
CycleEnergy analyse_cycle(const PiecewiseLinear& drive, const PiecewiseLinear& resist,
                          double balance_tolerance = 1e-6);

/// E(theta) - E(theta_start) for a steady cycle, J (for plots of energy or speed over the cycle).
double energy_at(const PiecewiseLinear& drive, const PiecewiseLinear& resist, double theta);

/// Factor k that makes `shape` scaled by k do the same work per cycle as `reference`: used when
/// a diagram gives the shape of one torque and its size follows from the energy balance (the
/// seed's triangular resisting torque whose peak is asked for).
/// @throws std::invalid_argument if `shape` does no work over its cycle.
double balance_scale(const PiecewiseLinear& reference, const PiecewiseLinear& shape);

struct FlywheelSizing {
  double omega_mean = 0;          ///< rad/s, (omega_max + omega_min) / 2
  double fluctuation = 0;         ///< delta, (omega_max - omega_min) / omega_mean
  double omega_max = 0;           ///< rad/s, omega_mean (1 + delta/2)
  double omega_min = 0;           ///< rad/s, omega_mean (1 - delta/2)
  double energy_excursion = 0;    ///< J
  double inertia_total = 0;       ///< kg*m^2 needed at the shaft: E / (delta omega_mean^2)
  double inertia_machine = 0;     ///< kg*m^2 the machine already has at the shaft
  double inertia_flywheel = 0;    ///< kg*m^2 to add: inertia_total - inertia_machine, or 0
  bool flywheel_needed = false;   ///< false when the machine alone keeps delta
  double fluctuation_without_flywheel = 0;  ///< delta with inertia_machine alone (inf if 0)
};

/// Sizes the flywheel for a largest energy excursion.
/// @param energy_excursion J, >= 0
/// @param omega_mean rad/s, > 0
/// @param fluctuation delta, in (0, 2)
/// @param inertia_machine kg*m^2 reduced to the same shaft, >= 0
/// @throws std::invalid_argument naming the parameter when one is out of range or not finite.
FlywheelSizing size_flywheel(double energy_excursion, double omega_mean, double fluctuation,
                             double inertia_machine);

/// The coefficient of fluctuation a given total inertia gives: E / (I omega_mean^2).
/// @throws std::invalid_argument if inertia <= 0 or omega_mean <= 0.
double fluctuation_for_inertia(double energy_excursion, double omega_mean, double inertia);

}  // namespace gearkit::dyn
