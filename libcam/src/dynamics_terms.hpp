#pragma once
// The follower's motion in SI and the lever at one cam angle, shared by the kinetostatics, the
// jump speed and the spring sizing (internal to libcam).
#include <gearkit/cam/follower_dynamics.hpp>

namespace gearkit::cam::detail {

/// q, dq/dtheta, d2q/dtheta2 in SI (m or rad, per rad), the lever h [m per unit q] and the contact.
struct Terms {
  ContactState contact;
  double q = 0, dq = 0, d2q = 0;
  double h = 0;
};

inline Terms terms_at(const CamDesign& d, double theta) {
  Terms t;
  t.contact = contact_at(d, theta);
  const double k = d.follower.motion == FollowerMotion::translating ? 1e-3 : 1.0;  // mm -> m
  t.q = t.contact.motion.s * k, t.dq = t.contact.motion.ds * k, t.d2q = t.contact.motion.d2s * k;
  t.h = lever(d, t.contact);
  return t;
}

/// Q = M q'' omega^2 + c q' omega + k q + F_0 + F_load (Norton, Design of Machinery, eq. 15.8).
inline double generalised_force(const FollowerTrain& train, const Terms& t, double omega) {
  return train.mass * t.d2q * omega * omega + train.damping * t.dq * omega + train.spring_rate * t.q + train.preload +
         train.load;
}

/// The follower body's own angular velocity [rad/s] for dq/dt = qdot.
inline double follower_spin(const CamDesign& d, const ContactState& c, double qdot) {
  return d.follower.motion == FollowerMotion::oscillating ? c.spin_per_s * qdot : 0.0;
}

}  // namespace gearkit::cam::detail
