#pragma once
// Normalised rise laws y(u) for cam motion: u = (theta - theta_0) / beta runs 0..1 over a segment of
// duration beta, y runs 0..1. The follower displacement of a rise of lift L is s = L y(u), so
// ds/dtheta = L y'(u) / beta, d2s/dtheta2 = L y''(u) / beta^2, d3s/dtheta3 = L y'''(u) / beta^3.
// All laws are analytic (Norton, "Design of Machinery", ch. 8; Chen, "Mechanics and Design of
// Cam Mechanisms"), so velocity, acceleration and jerk are exact, not differenced.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::cam {

enum class Law {
  uniform_velocity,    ///< y = u: infinite acceleration at the ends (a warning at every join)
  parabolic,           ///< constant acceleration, +4 then -4: jumps in acceleration
  simple_harmonic,     ///< y = (1 - cos pi u) / 2: acceleration jumps at the ends
  cycloidal,           ///< y = u - sin(2 pi u) / (2 pi): zero velocity and acceleration at both ends
  polynomial_345,      ///< y = 10u^3 - 15u^4 + 6u^5
  polynomial_4567,     ///< y = 35u^4 - 84u^5 + 70u^6 - 20u^7: zero jerk at both ends too
  modified_trapezoid,  ///< sine ramps over 1/8 of the rise, constant acceleration between
  modified_sine,       ///< sine ramp over 1/8, then a slower sine over 3/4 of the rise
};

/// y and its derivatives with respect to u.
struct LawValue {
  double y = 0, dy = 0, d2y = 0, d3y = 0;
};

/// The normalised law at u (clamped to [0, 1]).
LawValue evaluate(Law law, double u);

/// The name used in model files: "uniform_velocity", "parabolic", "simple_harmonic", "cycloidal",
/// "3-4-5", "4-5-6-7", "modified_trapezoid", "modified_sine".
std::string_view name_of(Law law);
std::optional<Law> law_from_name(std::string_view name);
/// Every law name, for messages ("expected one of ...").
std::vector<std::string> law_names();

/// The law as a formula in the text `u` stands for (GiNaC's and most parsers' syntax: `Pi`, `^`,
/// `sin`, `cos`), as course notes write it: y(u) and dy/du. nullopt for the laws pieced together
/// (parabolic, modified trapezoid, modified sine), which have no single expression.
struct LawFormula {
  std::string y, dy;
};
std::optional<LawFormula> law_formula(Law law, std::string_view u);

/// One piece of a law on [u0, u1] with its formulas (as law_formula writes them).
struct LawPiece {
  double u0 = 0, u1 = 1;
  LawFormula formula;
};
/// The law piece by piece: one piece [0, 1] for the single-expression laws, the pieces the law
/// is joined from otherwise (parabolic 2, modified trapezoid 5, modified sine 3), in closed form
/// with exact constants (Norton, Design of Machinery, sec. 8.4, whose decimals they reproduce:
/// modified sine y = 0.43990085 u - 0.0350062 sin(4 pi u) on [0, 1/8] is
/// (pi u - sin(4 pi u)/4)/(4 + pi)).
std::vector<LawPiece> law_pieces(Law law, std::string_view u);

/// The values of u inside (0, 1) where the law is pieced together, so that a derivative may
/// jump there: parabolic {1/2} (acceleration), modified trapezoid {1/8, 3/8, 5/8, 7/8} and
/// modified sine {1/8, 7/8} (continuous up to the jerk, checked all the same); none for the
/// others.
std::vector<double> law_breaks(Law law);

}  // namespace gearkit::cam
