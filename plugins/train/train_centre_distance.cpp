#include "train_centre_distance.hpp"

#include <gearkit/gear/gear_pair.hpp>

#include <cmath>
#include <numbers>
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
  const double alpha = 20.0 * std::numbers::pi / 180.0;
  try {
    const double a_d = gearkit::gear::reference_center_distance(z1, z2, *a.module_mm);
    const double alpha_w = gearkit::gear::working_pressure_angle(alpha, alpha, z1, z2, g1.x + g2.x);
    return std::fabs(gearkit::gear::center_distance(a_d, alpha, alpha_w));
  } catch (const std::domain_error&) {
    return std::nullopt;
  }
}

}  // namespace gearkit::plugins::train
