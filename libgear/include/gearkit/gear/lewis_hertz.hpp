#pragma once
// The teaching methods: Lewis bending and Hertz contact of spur gear teeth, with the Barth
// velocity factor, as the course notes and Shigley's "Mechanical Engineering Design" chapter 14
// (sections 14-1 and 14-5) present them. Any consistent units (N, mm, MPa or lbf, in, psi).
#include <gearkit/gear/rating.hpp>

namespace gearkit::gear::lewis {

/// Lewis form factor Y of a 20 deg full-depth tooth with the load at the tip (Shigley Table 14-2),
/// linear interpolation between the tabulated tooth counts, 0.485 for a rack (z >= 1e6 or more
/// than 400 teeth towards it). z >= 12.
double form_factor(double z);

/// Barth velocity factor K_v (Shigley Eq. 14-4 metric, V in m/s): cast profile (3.05 + V)/3.05,
/// cut or milled (6.1 + V)/6.1, hobbed or shaped (3.56 + sqrt V)/3.56, shaved or ground
/// (5.56 + sqrt V)/5.56.
double velocity_factor(LewisProfile profile, double V);

/// The same in US units (V in ft/min, Eq. 14-4): (600 + V)/600, (1200 + V)/1200,
/// (50 + sqrt V)/50, (78 + sqrt V)/78.
double velocity_factor_ft_min(LewisProfile profile, double V_ft_min);

/// Lewis bending stress sigma = K_v W_t / (b m Y) (Eq. 14-8; US: K_v W_t P / (F Y)).
double bending_stress(double W_t, double K_v, double b, double m, double Y);

/// Radius of curvature of the profile at the pitch point r = d sin(phi) / 2 (Eq. 14-12).
double pitch_point_radius(double d, double phi);

/// Hertz contact stress (magnitude) sigma_C = C_p sqrt(K_v W_t / (b cos phi) (1/r_1 +- 1/r_2))
/// (Eq. 14-14), `internal` subtracts 1/r_2.
double contact_stress(double C_p, double W_t, double K_v, double b, double phi, double r_1, double r_2, bool internal);

}  // namespace gearkit::gear::lewis
