#include "train_centre_distance.hpp"

#include <gearkit/gear/cylindrical_gear.hpp>
#include <gearkit/gear/gear_pair.hpp>

#include <cmath>
#include <stdexcept>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;

std::optional<double> working_centre_distance(const gt::Gear& a, const gt::Gear& b) {
  if (!a.module_mm || !b.module_mm || *a.module_mm != *b.module_mm) return std::nullopt;
  // libgear's signed convention: gear 1 external, gear 2 with z < 0 when internal.
  const gt::Gear& g1 = a.kind == gt::GearKind::internal ? b : a;
  const gt::Gear& g2 = a.kind == gt::GearKind::internal ? a : b;
  const int z1 = g1.z;
  const int z2 = g2.kind == gt::GearKind::internal ? -g2.z : g2.z;
  if (z1 + z2 == 0) return std::nullopt;
  namespace gg = gearkit::gear;
  const double alpha_n = g1.alpha_n, beta = g1.beta;
  try {
    const double alpha_t = gg::transverse_pressure_angle(alpha_n, beta);
    const double a_d = gg::reference_centre_distance(z1, z2, gg::transverse_module(*a.module_mm, beta));
    const double alpha_wt = gg::working_pressure_angle(alpha_t, alpha_n, z1, z2, g1.x + g2.x);
    return std::fabs(gg::centre_distance(a_d, alpha_t, alpha_wt));
  } catch (const std::domain_error&) {
    return std::nullopt;
  }
}

}  // namespace gearkit::plugins::train
