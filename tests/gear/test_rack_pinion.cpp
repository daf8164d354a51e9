// Tests for gearkit/gear/rack_pinion.hpp: a pinion meshing with a rack.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rack_pinion.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gg = gearkit::gear;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kAlpha = 20.0 * kDeg;

// A pinion of m = 3, z = 12, x = 0.6 (the 12-tooth gear of KHK's profile-shifted example) on a rack
// whose datum line lies H = 32 mm above its back; KHK's rack-and-pinion formula for the mounting
// distance, a = z m / 2 + H + x m, by hand: 18 + 32 + 1.8 = 51.8 mm.
gg::RackPinionInput khk_pinion() {
  gg::RackPinionInput in;
  in.z1 = 12;
  in.m_n = 3.0;
  in.x1 = 0.6;
  in.rack_height = 32.0;
  return in;
}

}  // namespace

TEST(RackPinion, MountingDistanceAndTravel) {
  const gg::RackPinionResult r = gg::compute_rack_pinion(khk_pinion());
  EXPECT_NEAR(r.H_0, 19.8, 1e-12);        // d/2 + x m
  EXPECT_NEAR(r.a_back, 51.8, 1e-12);     // KHK's a = z m / 2 + H + x m
  EXPECT_NEAR(r.d_a, 45.6, 1e-12);        // d + 2 m (1 + x), no tip shortening against a rack
  EXPECT_NEAR(r.d_f, 36.0 - 2.0 * 3.0 * (1.25 - 0.6), 1e-12);
  EXPECT_NEAR(r.travel_per_turn, 36.0 * std::numbers::pi, 1e-12);  // one turn rolls the reference circle once
  EXPECT_NEAR(r.c, 0.75, 1e-12);          // c* m = 0.25 * 3, whatever the shift
  // The datum distance gives the shift back.
  gg::RackPinionInput in = khk_pinion();
  in.H_0 = 19.8;
  in.x1 = 0.0;
  EXPECT_NEAR(gg::compute_rack_pinion(in).x1, 0.6, 1e-12);
}

TEST(RackPinion, ContactRatioByHand) {
  // z = 20, m = 1, x = 0, by hand (ISO 21771, z2 -> infinity):
  // g = sqrt(11^2 - (10 cos 20)^2) - 10 sin 20 + 1 / sin 20 = 5.71820 - 3.42020 + 2.92380,
  // eps = g / (pi cos 20) = 1.768824. z = 12, m = 3, x = 0.6: 1.427306.
  gg::RackPinionInput in;
  in.z1 = 20;
  in.m_n = 1.0;
  EXPECT_NEAR(gg::compute_rack_pinion(in).eps_alpha, 1.7688237, 1e-6);
  EXPECT_NEAR(gg::compute_rack_pinion(khk_pinion()).eps_alpha, 1.4273062, 1e-6);
}

// The rack is the limit of a gear whose teeth grow without end: the pair table of gear_pair.hpp
// with z2 = 100000 (and the working pressure angle, centre distance and tip shortening it finds)
// must give the rack's contact ratio within the O(1/z2) difference.
TEST(RackPinion, ContactRatioIsThePairsLimit) {
  for (double x : {0.0, 0.3, 0.6})
    for (double beta : {0.0, 15.0 * kDeg}) {
      gg::RackPinionInput rp;
      rp.z1 = 14;
      rp.m_n = 2.0;
      rp.x1 = x;
      rp.beta = beta;
      gg::GearPairInput pair;
      pair.z1 = 14;
      pair.z2 = 100000;
      pair.module = 2.0;
      pair.helix_angle = beta;
      pair.x1 = x;
      const double eps_pair = gg::compute_gear_pair(pair).pair.eps_alpha;
      EXPECT_NEAR(gg::compute_rack_pinion(rp).eps_alpha, eps_pair, 1e-4) << x << " " << beta;
    }
}

TEST(RackPinion, UndercutWarning) {
  // x_min = h_fP - rho_fP (1 - sin 20) - z sin^2(20) / 2 = 1.25 - 0.250032 - 0.701867 = 0.298101 for z = 12.
  gg::RackPinionInput in = khk_pinion();
  in.x1 = 0.0;
  const gg::RackPinionResult r = gg::compute_rack_pinion(in);
  EXPECT_NEAR(r.x_min, 0.2981010, 1e-6);
  bool undercut = false;
  for (const auto& w : r.warnings) undercut = undercut || w.find("undercut") != std::string::npos;
  EXPECT_TRUE(undercut);
  in.x1 = 0.3;
  for (const auto& w : gg::compute_rack_pinion(in).warnings) EXPECT_EQ(w.find("undercut"), std::string::npos) << w;
}

TEST(RackPinion, PinionSpanIsTheIsoFormula) {
  // W_k = m cos a ((k - 1/2) pi + z inv a) + 2 x m sin a (ISO 21771 / DIN 3960), evaluated here.
  const gg::RackPinionResult r = gg::compute_rack_pinion(khk_pinion());
  const double inv = std::tan(kAlpha) - kAlpha;
  const int k = r.k_span;
  // KHK/Niemann rule, by hand: cos a_x = 36 cos 20 / 39.6, a_x = 31.32 deg,
  // k = round(12/pi (tan a_x - 2 x tan 20 / 12 - inv 20) + 0.5) = round(2.63) = 3.
  EXPECT_EQ(k, 3);
  EXPECT_NEAR(r.W_k, 3.0 * std::cos(kAlpha) * ((k - 0.5) * std::numbers::pi + 12 * inv) + 2.0 * 0.6 * 3.0 * std::sin(kAlpha), 1e-9);
}

// A pin in the rack's tooth space, found by plane geometry: the space is bounded by the lines
// through (+-e/2, 0) inclined by alpha to the normal of the datum line; the pin's centre on the
// space's middle is where its distance to a flank line equals D/2 (bisection), and the measurement
// is that height plus D/2.
TEST(RackPinion, RackOverAPinByPlaneGeometry) {
  const double e = std::numbers::pi / 2.0;  // m = 1
  for (double D : {1.6716065, 1.5, 2.0}) {
    const double dir_x = std::sin(kAlpha), dir_y = std::cos(kAlpha);  // flank direction
    auto distance = [&](double y_c) {
      const double px = 0.0 - e / 2.0, py = y_c;  // from the flank's datum point to the centre
      return std::fabs(px * dir_y - py * dir_x);
    };
    double lo = -5.0, hi = 5.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (distance(mid) < D / 2.0 ? lo : hi) = mid;
    }
    EXPECT_NEAR(gg::rack_over_pin_height(e, kAlpha, D), lo + D / 2.0, 1e-9) << D;
  }
  // The pin touching on the datum line: D = e / cos a = 1.671607 m (KHK's rack pin pi m / (2 cos a)),
  // M = D/2 + D sin(a)/2 = 1.121665.
  EXPECT_NEAR(gg::rack_pin_diameter(e, kAlpha), 1.6716065, 1e-7);
  const gg::RackPinionResult r = gg::compute_rack_pinion(khk_pinion());
  EXPECT_NEAR(r.M_r, 3.0 * 1.1216648, 1e-6);
  EXPECT_NEAR(r.M_r_back, 32.0 + 3.0 * 1.1216648, 1e-6);
}

TEST(RackPinion, RackLengthForATravel) {
  // Tip circle r_a = 22.8, rack tip line at 19.8 - 3 = 16.8 from the pinion axis:
  // c = sqrt(22.8^2 - 16.8^2) = 15.414279; L = 200 + 2 c = 230.828558, 24.49 pitches -> 25 teeth.
  gg::RackPinionInput in = khk_pinion();
  in.travel = 200.0;
  const gg::RackPinionResult r = gg::compute_rack_pinion(in);
  EXPECT_NEAR(r.rack_length, 230.8285582, 1e-6);
  EXPECT_EQ(r.rack_teeth, 25);
}

// Forces: Shigley/Budynas eq. 13-39 with psi = beta; the force on the rack lies normal to the
// pinion's tooth line at the pitch point, found here by differentiating the right-hand helix
// (r cos t, r sin t, r t / tan beta) at t = -90 deg numerically.
TEST(RackPinion, ForcesAreNormalToTheToothLine) {
  const double beta = 15.0 * kDeg, alpha_t = std::atan(std::tan(kAlpha) / std::cos(beta)), d = 40.0;
  for (double T : {25.0, -25.0}) {
    const gg::RackForces f = gg::rack_forces(T, d, alpha_t, beta);
    const double F_t = 2000.0 * 25.0 / d;
    EXPECT_NEAR(f.F_t, F_t, 1e-12);
    EXPECT_NEAR(f.F_r, F_t * std::tan(kAlpha) / std::cos(beta), 1e-9);  // W_r = W sin phi_n, W_t = W cos phi_n cos psi
    EXPECT_NEAR(f.F_a, F_t * std::tan(beta), 1e-9);
    const double r = d / 2.0, t = -std::numbers::pi / 2.0, h = 1e-6;
    auto helix = [&](double u) { return std::array<double, 3>{r * std::cos(u), r * std::sin(u), r * u / std::tan(beta)}; };
    const auto p = helix(t + h), q = helix(t - h);
    const double tx = p[0] - q[0], tz = p[2] - q[2];
    EXPECT_NEAR(f.on_rack[0] * tx + f.on_rack[2] * tz, 0.0, 1e-6 * F_t * std::hypot(tx, tz));
    EXPECT_GT(f.on_rack[0] * T, 0.0);  // T > 0 about +z pushes the rack along +x (omega x r at (0, -r))
    EXPECT_LT(f.on_rack[1], 0.0);      // and away from the pinion
    EXPECT_NEAR(f.on_pinion[2], -f.on_rack[2], 1e-12);
  }
}

TEST(RackPinion, BadInputNamesTheField) {
  auto field_of = [](const gg::RackPinionInput& in) {
    try {
      gg::compute_rack_pinion(in);
    } catch (const gg::GeometryError& e) {
      return e.field();
    }
    return std::string("none");
  };
  gg::RackPinionInput in = khk_pinion();
  in.z1 = 2;
  EXPECT_EQ(field_of(in), "z1");
  in = khk_pinion();
  in.m_n = 0.0;
  EXPECT_EQ(field_of(in), "m_n");
  in = khk_pinion();
  in.H_0 = 100.0;  // x = (100 - 18) / 3 = 27
  EXPECT_EQ(field_of(in), "H_0");
  in = khk_pinion();
  in.travel = -1.0;
  EXPECT_EQ(field_of(in), "travel");
}
