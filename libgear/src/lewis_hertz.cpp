#include <gearkit/gear/lewis_hertz.hpp>

#include "rating_detail.hpp"

#include <gearkit/gear/iso6336_pitting.hpp>
#include <gearkit/gear/iso6336_load.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gearkit::gear::lewis {

double form_factor(double z) {
  struct P {
    double z, Y;
  };
  // Shigley, Table 14-2: 20 deg normal pressure angle, full-depth teeth, load at the tip.
  constexpr std::array<P, 25> table = {{{12, 0.245}, {13, 0.261}, {14, 0.277}, {15, 0.290}, {16, 0.296}, {17, 0.303},
                                         {18, 0.309}, {19, 0.314}, {20, 0.322}, {21, 0.328}, {22, 0.331}, {24, 0.337},
                                         {26, 0.346}, {28, 0.353}, {30, 0.359}, {34, 0.371}, {38, 0.384}, {43, 0.397},
                                         {50, 0.409}, {60, 0.422}, {75, 0.435}, {100, 0.447}, {150, 0.460}, {300, 0.472},
                                         {400, 0.480}}};
  if (z <= table.front().z) return table.front().Y;
  for (std::size_t i = 1; i < table.size(); ++i) {
    if (z <= table[i].z) {
      const P& a = table[i - 1];
      const P& b = table[i];
      return a.Y + (z - a.z) / (b.z - a.z) * (b.Y - a.Y);
    }
  }
  // Beyond 400 teeth towards the rack (Y = 0.485), linear in 1/z.
  return 0.485 - (0.485 - 0.480) * 400.0 / z;
}

double velocity_factor(LewisProfile profile, double V) {
  switch (profile) {
    case LewisProfile::cast: return (3.05 + V) / 3.05;
    case LewisProfile::cut: return (6.1 + V) / 6.1;
    case LewisProfile::hobbed: return (3.56 + std::sqrt(V)) / 3.56;
    case LewisProfile::ground: return (5.56 + std::sqrt(V)) / 5.56;
  }
  return 1.0;
}

double velocity_factor_ft_min(LewisProfile profile, double V) {
  switch (profile) {
    case LewisProfile::cast: return (600.0 + V) / 600.0;
    case LewisProfile::cut: return (1200.0 + V) / 1200.0;
    case LewisProfile::hobbed: return (50.0 + std::sqrt(V)) / 50.0;
    case LewisProfile::ground: return (78.0 + std::sqrt(V)) / 78.0;
  }
  return 1.0;
}

double bending_stress(double W_t, double K_v, double b, double m, double Y) { return K_v * W_t / (b * m * Y); }

double pitch_point_radius(double d, double phi) { return 0.5 * d * std::sin(phi); }

double contact_stress(double C_p, double W_t, double K_v, double b, double phi, double r_1, double r_2, bool internal) {
  const double curvature = 1.0 / r_1 + (internal ? -1.0 : 1.0) / r_2;
  return C_p * std::sqrt(K_v * W_t / (b * std::cos(phi)) * curvature);
}

}  // namespace gearkit::gear::lewis

namespace gearkit::gear::detail {

// Lewis bending (nominal stress against sigma_Flim) and Hertz contact at the pitch point
// (against sigma_Hlim), with the Barth velocity factor; helical gears by their normal module
// and virtual tooth count.
PairRating rate_lewis_hertz(const Mesh& m, const RatingInput& in) {
  PairRating r = operating_point(RatingMethod::lewis_hertz, m, in, in.T_1, in.n_1);
  const auto& f = in.factors;
  r.K_v = imposed_or(f, Factor::K_v, lewis::velocity_factor(in.lewis_profile, r.v));
  r.Z_E = imposed_or(f, Factor::Z_E, iso6336::elasticity_factor(in.material[0].E, in.material[0].nu, in.material[1].E, in.material[1].nu));
  const double r_1 = lewis::pitch_point_radius(m.d_w[0], m.alpha_wt);
  const double r_2 = lewis::pitch_point_radius(m.d_w[1], m.alpha_wt);
  const double W = r.F_t * in.K_A * r.K_gamma;  // planets: the share of the most loaded one
  const double sigma_H = lewis::contact_stress(r.Z_E, W, r.K_v, m.b, m.alpha_wt, r_1, r_2, m.internal);
  r.extra = {{"r_1_mm", r_1}, {"r_2_mm", r_2}};
  for (int i = 0; i < 2; ++i) {
    GearRating& g = r.gear[i];
    const Material& mat = in.material[i];
    g.n = i == 0 ? in.n_1 : in.n_1 / m.u;
    g.N_L = g.n * 60.0 * in.life_h * in.cycles_per_rev[i];
    const double Y = imposed_or(f, per_gear(Factor::Y1, i), lewis::form_factor(m.z_n[i]));
    g.sigma_F = lewis::bending_stress(W, r.K_v, m.b, m.m_n, Y);
    g.sigma_H = sigma_H;
    g.sigma_FG = mat.sigma_Flim;
    g.sigma_HG = mat.sigma_Hlim;
    g.sigma_FP = g.sigma_FG / in.S_Fmin;
    g.sigma_HP = g.sigma_HG / in.S_Hmin;
    g.S_F = g.sigma_FG / g.sigma_F;
    g.S_H = g.sigma_HG / g.sigma_H;
    g.extra = {{"Y", Y}};
  }
  if (m.beta != 0.0) r.warnings.push_back("Lewis/Hertz: the helix is only taken into account through m_n and z_n");
  return r;
}

}  // namespace gearkit::gear::detail
