#include <gearkit/gear/rack.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gearkit::gear {

double clearance_coefficient(const Rack& rack) { return rack.h_fP - rack.h_aP; }

double max_fillet_radius_coefficient(const Rack& rack) {
  // The tip circle touches the tip line and the flank; its centre must not pass the tooth
  // centre line: x_c = pi/4 - (h_fP - rho) tan(a) - rho / cos(a) >= 0.
  const double a = rack.alpha_P;
  return (std::numbers::pi / 4.0 - rack.h_fP * std::tan(a)) / (1.0 / std::cos(a) - std::tan(a));
}

void validate(const Rack& rack) {
  if (!(rack.alpha_P > 0.0 && rack.alpha_P < std::numbers::pi / 4.0)) {
    throw std::invalid_argument("rack pressure angle must lie in (0, 45) deg, found " +
                                std::to_string(rack.alpha_P * 180.0 / std::numbers::pi) + " deg");
  }
  if (!(rack.h_aP > 0.0)) {
    throw std::invalid_argument("rack addendum coefficient h_aP* must be > 0, found " + std::to_string(rack.h_aP));
  }
  if (!(rack.h_fP >= rack.h_aP)) {
    throw std::invalid_argument("rack dedendum coefficient h_fP* must be >= h_aP*, found " + std::to_string(rack.h_fP));
  }
  const double rho_max = max_fillet_radius_coefficient(rack);
  if (!(rack.rho_fP >= 0.0 && rack.rho_fP <= rho_max + 1e-12)) {
    throw std::invalid_argument("rack root radius coefficient rho_fP* must lie in [0, " + std::to_string(rho_max) +
                                "], found " + std::to_string(rack.rho_fP));
  }
}

}  // namespace gearkit::gear
