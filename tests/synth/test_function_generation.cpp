// libsynth function_generation.hpp: Chebyshev spacing, Freudenstein's equation for the four-bar
// and its slider-crank analogue (exact for three points, least squares for more), and the
// structural error, checked against hand derivations, linkages whose dimensions are known, and
// the solver driving the written mechanism file.
#include "synth_test_support.hpp"

#include <gearkit/synth/function_generation.hpp>
#include <gearkit/synth/mechanism_writer.hpp>

#include <gtest/gtest.h>

using namespace gearkit::synth;
using namespace gearkit::synth::testing;

namespace {

// Rocker angle of the reference four-bar (O2 O4 on x) at crank angle phi, by libkin.
std::vector<double> reference_psi(const std::vector<double>& phi) {
  Driven d = Driven::from_file(std::string(GEARKIT_SOURCE_DIR) + "/examples/mechanisms/four_bar.yaml");
  std::vector<double> psi;
  for (double p : phi) {
    EXPECT_TRUE(d.drive_to(p));
    psi.push_back(d.output("theta4"));
  }
  return psi;
}

}  // namespace

TEST(FunctionGeneration, ChebyshevSpacingOfThreePoints) {
  // x_j = 1.5 - 0.5 cos((2j - 1) 30 deg): 1.5 -+ 0.5 cos 30 deg and 1.5.
  const auto x = chebyshev_spacing(1, 2, 3);
  ASSERT_EQ(x.size(), 3u);
  EXPECT_NEAR(x[0], 1.5 - 0.25 * std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(x[1], 1.5, 1e-15);
  EXPECT_NEAR(x[2], 1.5 + 0.25 * std::sqrt(3.0), 1e-15);
  EXPECT_THROW(chebyshev_spacing(1, 1, 3), std::invalid_argument);
}

TEST(FunctionGeneration, FreudensteinRecoversAKnownFourBar) {
  // Reference four-bar a = 40, b = 120, c = 80, d = 100 mm: K1 = d/a = 2.5, K2 = d/c = 1.25,
  // K3 = (a^2 - b^2 + c^2 + d^2)/(2ac) = 3600/6400 = 0.5625.
  const std::vector<double> phi{20 * deg, 75 * deg, 140 * deg};
  const auto K = freudenstein_coefficients(phi, reference_psi(phi));
  // libkin's angles carry its 1e-10 residual tolerance, so K to 1e-7.
  EXPECT_NEAR(K.K1, 2.5, 1e-7);
  EXPECT_NEAR(K.K2, 1.25, 1e-7);
  EXPECT_NEAR(K.K3, 0.5625, 1e-7);
  const auto f = four_bar_from_coefficients(K, 0.1);
  EXPECT_NEAR(f.linkage.crank, 0.04, 1e-9);
  EXPECT_NEAR(f.linkage.coupler, 0.12, 1e-9);
  EXPECT_NEAR(f.linkage.rocker, 0.08, 1e-9);
  // Fifty exact pairs: least squares gives the same linkage.
  std::vector<double> many;
  for (int k = 0; k < 50; ++k) many.push_back(k * 7 * deg);
  const auto L = freudenstein_coefficients(many, reference_psi(many));
  EXPECT_NEAR(L.K1, 2.5, 1e-7);
  EXPECT_NEAR(L.K3, 0.5625, 1e-7);
}

TEST(FunctionGeneration, SliderCrankAnalogueRecoversAKnownSliderCrank) {
  // a = 50, b = 200, e = 20 mm: K1 = 2a = 0.1 m, K2 = 2ae = 0.002 m^2, K3 = a^2 + e^2 - b^2.
  SliderCrank k;
  k.crank = 0.05;
  k.rod = 0.2;
  k.offset = 0.02;
  std::vector<double> phi{10 * deg, 100 * deg, 230 * deg}, s;
  for (double p : phi) s.push_back(*slider_position(k, p));
  const auto K = slider_crank_coefficients(phi, s);
  EXPECT_NEAR(K.K1, 0.1, 1e-12);
  EXPECT_NEAR(K.K2, 0.002, 1e-12);
  EXPECT_NEAR(K.K3, 0.0025 + 0.0004 - 0.04, 1e-12);
  const auto back = slider_crank_from_coefficients(K);
  EXPECT_NEAR(back.linkage.rod, 0.2, 1e-12);
  EXPECT_NEAR(back.linkage.offset, 0.02, 1e-12);
}

TEST(FunctionGeneration, NoFourBarWhenTheCouplerWouldBeImaginary) {
  EXPECT_THROW(four_bar_from_coefficients({1, 1, 10}, 0.1), NoSolution);  // b^2 = 0.02 - 0.2 < 0
  EXPECT_THROW(four_bar_from_coefficients({0, 1, 0.5}, 0.1), NoSolution);
}

TEST(FunctionGeneration, Log10GeneratorIsExactAtTheChebyshevPoints) {
  const FunctionResult r = synthesize_function(log10_task());
  ASSERT_TRUE(r.defects.ok());
  // At the precision points the linkage generates f exactly: its rocker angle there, by the
  // closed-form position, maps back to log10(x).
  for (std::size_t j = 0; j < 3; ++j) {
    const double x = r.precision_x[j];
    const double psi = pose_at(r.four_bar.linkage, r.precision_theta2[j])->theta4 - r.four_bar.rocker_offset;
    const double y = std::log10(2.0) * std::remainder(psi - 225 * deg, 2 * pi) / (60 * deg);
    EXPECT_NEAR(y, std::log10(x), 1e-12);
  }
  // The structural error changes sign at each precision point (x = 1.067, 1.5, 1.933) and stays
  // below 0.5 % of the y range here.
  EXPECT_LT(r.max_error, 0.005 * std::log10(2.0));
  int sign_changes = 0;
  for (std::size_t k = 1; k < r.samples.size(); ++k) sign_changes += (r.samples[k].error > 0) != (r.samples[k - 1].error > 0);
  EXPECT_EQ(sign_changes, 3);
}

TEST(FunctionGeneration, WrittenGeneratorReachesThePrecisionPointsInTheSolver) {
  const FunctionResult r = synthesize_function(log10_task());
  const FourBar& f = r.four_bar.linkage;
  Driven d = Driven::from_text(to_mechanism_yaml(four_bar_sketch(f, 90 * deg, 60 * deg, 1, "log10")));
  for (std::size_t j = 0; j < 3; ++j) {
    ASSERT_TRUE(d.drive_to(r.precision_theta2[j]));
    const double psi = d.output("theta4") - r.four_bar.rocker_offset;
    EXPECT_NEAR(std::log10(2.0) * std::remainder(psi - 225 * deg, 2 * pi) / (60 * deg), std::log10(r.precision_x[j]), 1e-9);
  }
}

TEST(FunctionGeneration, LeastSquaresMinimisesTheEquationResidual) {
  FunctionTask t = log10_task();
  t.method = FitMethod::least_squares;
  t.fit_points = 30;
  const FunctionResult r = synthesize_function(t);
  const auto residual = [&](const Coefficients& K) {
    double sum = 0;
    for (double x : r.precision_x) {
      const double phi = 90 * deg + (x - 1) * 60 * deg, psi = 225 * deg + std::log10(x) / std::log10(2.0) * 60 * deg;
      const double e = K.K1 * std::cos(psi) - K.K2 * std::cos(phi) + K.K3 - std::cos(phi - psi);
      sum += e * e;
    }
    return sum;
  };
  const double best = residual(r.K);
  for (double h : {1e-4, -1e-4}) {
    EXPECT_GT(residual({r.K.K1 + h, r.K.K2, r.K.K3}), best);
    EXPECT_GT(residual({r.K.K1, r.K.K2 + h, r.K.K3}), best);
    EXPECT_GT(residual({r.K.K1, r.K.K2, r.K.K3 + h}), best);
  }
}

TEST(FunctionGeneration, SliderCrankGeneratorThroughTheSolver) {
  FunctionTask t;  // s = 80 mm - 60 mm * x^2 while the crank turns 120 deg from 30 deg
  t.f = [](double x) { return x * x; };
  t.x_start = 0;
  t.x_end = 1;
  t.input_start = 30 * deg;
  t.input_range = 120 * deg;
  t.output_start = 0.08;
  t.output_range = -0.06;
  t.type = GeneratorType::slider_crank;
  const FunctionResult r = synthesize_function(t);
  ASSERT_TRUE(r.defects.ok());
  const SliderCrank& k = r.slider_crank.linkage;
  Driven d = Driven::from_text(to_mechanism_yaml(slider_crank_sketch(k, 30 * deg + r.slider_crank.crank_offset, 120 * deg, 1, "x^2")));
  for (std::size_t j = 0; j < 3; ++j) {
    ASSERT_TRUE(d.drive_to(r.precision_theta2[j]));
    EXPECT_NEAR(d.output("s"), 0.08 - 0.06 * r.precision_x[j] * r.precision_x[j], 1e-10);
  }
}

TEST(FunctionGeneration, BadTasksAreRejected) {
  FunctionTask t = log10_task();
  t.x_end = 1;
  EXPECT_THROW(synthesize_function(t), std::invalid_argument);
  t = log10_task();
  t.precision_x = {1.1, 3.0, 1.9};
  EXPECT_THROW(synthesize_function(t), std::invalid_argument);
  t = log10_task();
  t.f = [](double x) { return std::log10(x - 1.5); };  // NaN below 1.5
  EXPECT_THROW(synthesize_function(t), std::invalid_argument);
  t = log10_task();
  t.error_samples = 1;
  EXPECT_THROW(synthesize_function(t), std::invalid_argument);
}
