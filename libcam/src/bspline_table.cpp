// B-spline table segments: the table's points are the control polygon of a clamped uniform
// B-spline curve (theta(u), s(u)); s is evaluated as a function of theta by inverting theta(u).
// Each knot span is converted once to power form, so an evaluation is a few Newton steps on a
// polynomial of degree <= 5.
#include "segment_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gearkit::cam {
namespace {

/// Derivatives 0..n of the p + 1 non-zero basis functions on span i at u (Piegl & Tiller, The
/// NURBS Book, algorithm A2.3): ders[k][j] is the k-th derivative of N_{i-p+j,p}(u).
std::vector<std::vector<double>> basis_derivatives(int i, double u, int p, int n, const std::vector<double>& U) {
  std::vector<std::vector<double>> ndu(p + 1, std::vector<double>(p + 1)), a(2, std::vector<double>(p + 1));
  std::vector<double> left(p + 1), right(p + 1);
  std::vector<std::vector<double>> ders(n + 1, std::vector<double>(p + 1, 0.0));
  ndu[0][0] = 1;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1;
    for (int k = 1; k <= n; ++k) {
      double d = 0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= n; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= factor;
    factor *= p - k;
  }
  return ders;
}

/// A polynomial in v in [0, 1] (ascending coefficients) and its first three derivatives.
std::array<double, 4> evaluate(const std::vector<double>& c, double v) {
  std::array<double, 4> d{0, 0, 0, 0};
  for (std::size_t j = c.size(); j-- > 0;) {
    d[3] = d[3] * v + d[2];
    d[2] = d[2] * v + d[1];
    d[1] = d[1] * v + d[0];
    d[0] = d[0] * v + c[j];
  }
  d[2] *= 2, d[3] *= 6;
  return d;
}

class BSplineTable : public SegmentCurve {
 public:
  BSplineTable(const std::vector<double>& x, const std::vector<double>& y) {
    const int n = static_cast<int>(x.size());
    const int p = std::min(5, n - 1);
    std::vector<double> U(p + 1, 0.0);
    const int inner = n - p - 1;
    for (int k = 1; k <= inner; ++k) U.push_back(static_cast<double>(k) / (inner + 1));
    U.insert(U.end(), p + 1, 1.0);
    for (int i = p; i < n; ++i) {  // span [U_i, U_i+1)
      const double du = U[i + 1] - U[i];
      const auto ders = basis_derivatives(i, U[i], p, p, U);
      std::vector<double> cx(p + 1, 0.0), cy(p + 1, 0.0);
      double scale = 1;  // du^k / k!
      for (int k = 0; k <= p; ++k) {
        for (int j = 0; j <= p; ++j) {
          cx[k] += ders[k][j] * x[i - p + j];
          cy[k] += ders[k][j] * y[i - p + j];
        }
        cx[k] *= scale, cy[k] *= scale;
        scale *= du / (k + 1);
      }
      start_.push_back(cx[0]);
      theta_.push_back(std::move(cx));
      s_.push_back(std::move(cy));
    }
    end_ = x.back();
  }

  Motion at(double theta) const override {
    const auto it = std::upper_bound(start_.begin(), start_.end(), theta);
    const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - start_.begin()), 1, start_.size()) - 1;
    const double v = parameter_of(k, theta);
    const auto t = evaluate(theta_[k], v), s = evaluate(s_[k], v);
    // Chain rule with a = dtheta/dv > 0 (increasing control angles make theta(v) increasing).
    const double a = t[1], a1 = t[2], a2 = t[3], b = s[1], b1 = s[2], b2 = s[3];
    const double num2 = b1 * a - b * a1;
    return {s[0], b / a, num2 / (a * a * a), ((b2 * a - b * a2) * a - 3 * a1 * num2) / (a * a * a * a * a)};
  }
  Motion left_at(double theta) const override { return at(theta); }  // C4 with simple inner knots
  std::vector<double> inner_breaks() const override { return {}; }

 private:
  /// v in [0, 1] with theta_k(v) = theta: safeguarded Newton iteration.
  double parameter_of(std::size_t k, double theta) const {
    const double t0 = start_[k], t1 = k + 1 < start_.size() ? start_[k + 1] : end_;
    double lo = 0, hi = 1;
    double v = std::clamp((theta - t0) / (t1 - t0), 0.0, 1.0);
    for (int it = 0; it < 60; ++it) {
      const auto t = evaluate(theta_[k], v);
      const double f = t[0] - theta;
      (f > 0 ? hi : lo) = v;
      double next = v - f / t[1];
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - v) <= 1e-15) return next;
      v = next;
    }
    return v;
  }

  std::vector<double> start_;  // theta at the start of each span
  std::vector<std::vector<double>> theta_, s_;
  double end_ = 0;
};

}  // namespace

std::shared_ptr<SegmentCurve> bspline_table(const std::vector<double>& x, const std::vector<double>& y,
                                            TableEnds ends) {
  if (ends != TableEnds::zero_slope) return std::make_shared<BSplineTable>(x, y);
  // Four equal values at each end make velocity, acceleration and jerk vanish there.
  std::vector<double> cx{x.front()}, cy{y.front()};
  const double q0 = (x[1] - x[0]) / 4, q1 = (x[x.size() - 1] - x[x.size() - 2]) / 4;
  for (int k = 1; k <= 3; ++k) cx.push_back(x.front() + k * q0), cy.push_back(y.front());
  for (std::size_t i = 1; i + 1 < x.size(); ++i) cx.push_back(x[i]), cy.push_back(y[i]);
  for (int k = 3; k >= 1; --k) cx.push_back(x.back() - k * q1), cy.push_back(y.back());
  cx.push_back(x.back()), cy.push_back(y.back());
  return std::make_shared<BSplineTable>(cx, cy);
}

}  // namespace gearkit::cam
