#include <gearkit/cam/motion_law.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gearkit::cam {
namespace {

constexpr double pi = std::numbers::pi;

/// One piece of a piecewise acceleration a(u) = A sin(w (u - u0) + phi) + B on [u0, u1].
struct AccelerationPiece {
  double u0, u1, A, w, phi, B;
};

/// A law defined by its acceleration pieces, integrated in closed form from y(0) = y'(0) = 0 and
/// scaled so that y(1) = 1. This is how the modified trapezoid and modified sine are defined
/// (Norton, Design of Machinery, sec. 8.4: sinusoidal ramps joined to constant or slower
/// sinusoidal acceleration); integrating here keeps every constant exact instead of copying
/// rounded coefficients from a table.
class PiecewiseLaw {
 public:
  explicit PiecewiseLaw(std::vector<AccelerationPiece> pieces) : pieces_(std::move(pieces)) {
    scale_ = 1;
    double y = 0, v = 0;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      start_y_.push_back(y);
      start_v_.push_back(v);
      const LawValue end = eval_piece(i, pieces_[i].u1);
      y = end.y, v = end.dy;
    }
    scale_ = 1 / y;
  }

  LawValue at(double u) const {
    std::size_t i = 0;
    while (i + 1 < pieces_.size() && u > pieces_[i].u1) ++i;
    LawValue r = eval_piece(i, u);
    r.y *= scale_, r.dy *= scale_, r.d2y *= scale_, r.d3y *= scale_;
    return r;
  }

 private:
  LawValue eval_piece(std::size_t i, double u) const {
    const AccelerationPiece& p = pieces_[i];
    const double t = u - p.u0;
    const double arg = p.w * t + p.phi;
    LawValue r;
    r.d3y = p.A * p.w * std::cos(arg);
    r.d2y = p.A * std::sin(arg) + p.B;
    r.dy = start_v_[i] + p.B * t - p.A / p.w * (std::cos(arg) - std::cos(p.phi));
    r.y = start_y_[i] + start_v_[i] * t + 0.5 * p.B * t * t -
          p.A / p.w * ((std::sin(arg) - std::sin(p.phi)) / p.w - std::cos(p.phi) * t);
    return r;
  }

  std::vector<AccelerationPiece> pieces_;
  std::vector<double> start_y_, start_v_;
  double scale_ = 1;
};

const PiecewiseLaw& modified_trapezoid_law() {
  // Sine ramp up over 1/8, constant, cosine down through zero over 1/4, constant, ramp back.
  static const PiecewiseLaw law({{0, 0.125, 1, 4 * pi, 0, 0},
                                 {0.125, 0.375, 0, 1, 0, 1},
                                 {0.375, 0.625, 1, 4 * pi, pi / 2, 0},
                                 {0.625, 0.875, 0, 1, 0, -1},
                                 {0.875, 1, 1, 4 * pi, -pi / 2, 0}});
  return law;
}

const PiecewiseLaw& modified_sine_law() {
  // Sine ramp over 1/8 (period 1/2), then a cosine of period 3/2 through 3/4, then ramp down.
  static const PiecewiseLaw law({{0, 0.125, 1, 4 * pi, 0, 0},
                                 {0.125, 0.875, 1, 4 * pi / 3, pi / 2, 0},
                                 {0.875, 1, 1, 4 * pi, -pi / 2, 0}});
  return law;
}

struct NamedLaw {
  Law law;
  std::string_view name;
};

constexpr std::array<NamedLaw, 8> kNames{{{Law::uniform_velocity, "uniform_velocity"},
                                          {Law::parabolic, "parabolic"},
                                          {Law::simple_harmonic, "simple_harmonic"},
                                          {Law::cycloidal, "cycloidal"},
                                          {Law::polynomial_345, "3-4-5"},
                                          {Law::polynomial_4567, "4-5-6-7"},
                                          {Law::modified_trapezoid, "modified_trapezoid"},
                                          {Law::modified_sine, "modified_sine"}}};

}  // namespace

LawValue evaluate(Law law, double u) {
  u = std::clamp(u, 0.0, 1.0);
  switch (law) {
    case Law::uniform_velocity:
      return {u, 1, 0, 0};
    case Law::parabolic:
      if (u < 0.5) return {2 * u * u, 4 * u, 4, 0};
      return {1 - 2 * (1 - u) * (1 - u), 4 * (1 - u), -4, 0};
    case Law::simple_harmonic:
      return {(1 - std::cos(pi * u)) / 2, pi / 2 * std::sin(pi * u), pi * pi / 2 * std::cos(pi * u),
              -pi * pi * pi / 2 * std::sin(pi * u)};
    case Law::cycloidal:
      return {u - std::sin(2 * pi * u) / (2 * pi), 1 - std::cos(2 * pi * u), 2 * pi * std::sin(2 * pi * u),
              4 * pi * pi * std::cos(2 * pi * u)};
    case Law::polynomial_345: {
      const double u2 = u * u, u3 = u2 * u;
      return {u3 * (10 - 15 * u + 6 * u2), 30 * u2 * (1 - 2 * u + u2), 60 * u * (1 - 3 * u + 2 * u2),
              60 * (1 - 6 * u + 6 * u2)};
    }
    case Law::polynomial_4567: {
      const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
      return {u4 * (35 - 84 * u + 70 * u2 - 20 * u3), 140 * u3 * (1 - 3 * u + 3 * u2 - u3),
              420 * u2 * (1 - 4 * u + 5 * u2 - 2 * u3), 840 * u * (1 - 6 * u + 10 * u2 - 5 * u3)};
    }
    case Law::modified_trapezoid:
      return modified_trapezoid_law().at(u);
    case Law::modified_sine:
      return modified_sine_law().at(u);
  }
  return {};
}

std::optional<LawFormula> law_formula(Law law, std::string_view u_text) {
  const std::string u = "(" + std::string(u_text) + ")";
  const auto power = [&u](int k) { return u + "^" + std::to_string(k); };
  switch (law) {
    case Law::uniform_velocity: return LawFormula{u, "1"};
    case Law::simple_harmonic: return LawFormula{"(1-cos(Pi*" + u + "))/2", "Pi/2*sin(Pi*" + u + ")"};
    case Law::cycloidal: return LawFormula{u + "-sin(2*Pi*" + u + ")/(2*Pi)", "1-cos(2*Pi*" + u + ")"};
    case Law::polynomial_345:
      return LawFormula{"10*" + power(3) + "-15*" + power(4) + "+6*" + power(5), "30*" + power(2) + "-60*" + power(3) + "+30*" + power(4)};
    case Law::polynomial_4567:
      return LawFormula{"35*" + power(4) + "-84*" + power(5) + "+70*" + power(6) + "-20*" + power(7),
                        "140*" + power(3) + "-420*" + power(4) + "+420*" + power(5) + "-140*" + power(6)};
    case Law::parabolic:
    case Law::modified_trapezoid:
    case Law::modified_sine: return std::nullopt;
  }
  return std::nullopt;
}

std::vector<LawPiece> law_pieces(Law law, std::string_view u_text) {
  if (const auto f = law_formula(law, u_text)) return {{0, 1, *f}};
  const std::string u = "(" + std::string(u_text) + ")";
  // Derived by integrating the acceleration pieces above from y(0) = y'(0) = 0 and dividing by
  // y(1): 1/(pi + 2) for the modified trapezoid, 1/(4 + pi) for the modified sine.
  const auto mt = [](const std::string& y, const std::string& dy) { return LawFormula{"(" + y + ")/(Pi+2)", "(" + dy + ")/(Pi+2)"}; };
  const auto ms = [](const std::string& y, const std::string& dy) { return LawFormula{"(" + y + ")/(4+Pi)", "(" + dy + ")/(4+Pi)"}; };
  switch (law) {
    case Law::parabolic:
      return {{0, 0.5, {"2*" + u + "^2", "4*" + u}}, {0.5, 1, {"1-2*(1-" + u + ")^2", "4*(1-" + u + ")"}}};
    case Law::modified_trapezoid:
      return {{0, 0.125, mt("2*" + u + "-sin(4*Pi*" + u + ")/(2*Pi)", "2-2*cos(4*Pi*" + u + ")")},
              {0.125, 0.375, mt("4*Pi*" + u + "^2+(2-Pi)*" + u + "+Pi/16-1/(2*Pi)", "8*Pi*" + u + "+2-Pi")},
              {0.375, 0.625, mt("(2+2*Pi)*" + u + "+sin(4*Pi*" + u + ")/(2*Pi)-Pi/2", "2+2*Pi+2*cos(4*Pi*" + u + ")")},
              {0.625, 0.875, mt("-4*Pi*" + u + "^2+(7*Pi+2)*" + u + "-2*Pi-Pi/16+1/(2*Pi)", "7*Pi+2-8*Pi*" + u)},
              {0.875, 1, mt("Pi+2*" + u + "-sin(4*Pi*" + u + ")/(2*Pi)", "2-2*cos(4*Pi*" + u + ")")}};
    case Law::modified_sine:
      return {{0, 0.125, ms("Pi*" + u + "-sin(4*Pi*" + u + ")/4", "Pi-Pi*cos(4*Pi*" + u + ")")},
              {0.125, 0.875, ms("2+Pi*" + u + "-9/4*cos(4*Pi*" + u + "/3-Pi/6)", "Pi+3*Pi*sin(4*Pi*" + u + "/3-Pi/6)")},
              {0.875, 1, ms("4+Pi*" + u + "-sin(4*Pi*" + u + ")/4", "Pi-Pi*cos(4*Pi*" + u + ")")}};
    default: return {};
  }
}

std::string_view name_of(Law law) {
  for (const NamedLaw& n : kNames)
    if (n.law == law) return n.name;
  return "?";
}

std::optional<Law> law_from_name(std::string_view name) {
  for (const NamedLaw& n : kNames)
    if (n.name == name) return n.law;
  return std::nullopt;
}

std::vector<double> law_breaks(Law law) {
  switch (law) {
    case Law::parabolic: return {0.5};
    case Law::modified_trapezoid: return {0.125, 0.375, 0.625, 0.875};
    case Law::modified_sine: return {0.125, 0.875};
    default: return {};
  }
}

std::vector<std::string> law_names() {
  std::vector<std::string> out;
  for (const NamedLaw& n : kNames) out.emplace_back(n.name);
  return out;
}

}  // namespace gearkit::cam
