#pragma once
// Private to libgear: the pieces shared by the external (rack-generated) and internal
// (shaper-generated) tooth forms: the transverse section, the involute flank, sampling a curve
// within a tolerance and the exact crossing of a generated fillet with the involute.
//
// Polar convention: radius r and angle eta from the space centre line (the +y axis), positive
// towards +x, so the right side of tooth space 0 has eta > 0.
#include <gearkit/gear/tooth_form.hpp>

#include <functional>
#include <vector>

namespace gearkit::gear::detail {

struct Polar {
  double r = 0, eta = 0;
};

Polar to_polar(Point2 p);
Point2 to_point(Polar q);

/// The transverse section of a gear (magnitudes, mm and rad).
struct Section {
  double r = 0;         ///< reference radius
  double m_t = 0;       ///< transverse module
  double alpha_t = 0;   ///< transverse pressure angle
  double r_b = 0;       ///< base radius
  double r_a = 0;       ///< tip radius
  double e_over_d = 0;  ///< half the space angle on the reference circle, e_t / d
  double x_e = 0;       ///< generating shift coefficient x + A_sn / (2 m_n tan alpha_n)
};

/// @throws std::invalid_argument if z == 0, m_n <= 0 or the tolerance is not in [1e-7, 1] mm.
Section section_of(const ToothFormSpec& spec);

/// Half space angle of the involute flank at radius r_y >= r_b. An external gear's space widens
/// outwards, a ring's space narrows outwards (it is shaped like a pinion tooth).
double involute_eta(const Section& c, bool ring, double r_y);

/// The involute flank between two radii as a curve of its roll parameter xi = tan(alpha_y)
/// (smooth down to the base circle, where d(eta)/dr is infinite).
struct InvoluteCurve {
  const Section& c;
  bool ring;
  Point2 operator()(double xi) const;
  static double xi_at(const Section& c, double r) ;
};

/// A plane curve t -> point on [t0, t1].
using Curve = std::function<Point2(double)>;

/// Appends points of `curve` from t0 to t1 (both ends included) such that every chord between
/// consecutive points stays within `tolerance` (mm) of the curve: segments are halved until the
/// curve's distance from the chord, probed at the quarter points, is below half the tolerance.
/// @throws std::runtime_error past 200000 points (a tolerance far below the options' limit).
void sample_within(const Curve& curve, double t0, double t1, double tolerance, std::vector<Point2>& out);

/// The first parameter in [t0, t1] where the generated fillet (eta_f(t)) passes from the space
/// side of the involute (eta_f > eta_i: wider space) to its tooth side, solved to 1e-14 by
/// bisection after a scan of 512 steps; t1 if it never does.
double fillet_involute_crossing(const Curve& fillet, const Section& c, bool ring, double t0, double t1);

/// Solves f(t) = 0 on [a, b] by bisection (f(a) and f(b) of opposite signs), to 1e-15 relative.
double bisect(const std::function<double(double)>& f, double a, double b);

/// Assembles the flank of space 0 (polar, root to tip): the fillet samples on [t_root, t_join],
/// then the involute from the fillet's end radius to r_to (external: the tip; ring: the tip too,
/// which is the smaller radius).
std::vector<Polar> join_fillet_and_involute(const Curve& fillet, double t_root, double t_join, const Section& c,
                                            bool ring, double tolerance);

/// The flank of ring space 0 (polar, root to tip): shaper-cut fillet, then the involute.
std::vector<Polar> ring_flank(const ToothFormSpec& spec, const Section& c);

}  // namespace gearkit::gear::detail
