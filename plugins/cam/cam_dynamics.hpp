#pragma once
// The cam command's dynamics: the follower train at the design speed (libcam's kinetostatics and
// flexible response), the spring it needs, the jump speed, a speed sweep, residual vibration.
#include "cam_model.hpp"

#include <gearkit/cam/follower_dynamics.hpp>
#include <gearkit/cam/follower_vibration.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::cam {

/// The residual vibration one law would leave, for the comparison table.
struct LawResidual {
  gearkit::cam::Law law;
  double amplitude = 0;  ///< [m | rad]
};

struct CamDynamics {
  gearkit::cam::FollowerTrain train;  ///< as analysed: the sized rate and preload filled in
  bool rate_sized = false, preload_sized = false;
  std::optional<gearkit::cam::SpringSizing> needed;  ///< given both: the preload the given rate needs
  double omega = 0;                                  ///< design speed [rad/s]
  double sizing_omega = 0;                           ///< the speed a sized spring holds to: omega x jump margin [rad/s]
  std::vector<gearkit::cam::DynamicState> states;    ///< over the turn at the design speed
  std::optional<gearkit::cam::JumpSpeed> jump;       ///< force closure; none up to the search speed
  double least_margin = 0;                           ///< least Q - F_min h at the design speed
  std::optional<gearkit::cam::SpeedSweep> sweep;
  std::optional<gearkit::cam::FlexibleResponse> flexible;
  std::vector<gearkit::cam::ResidualVibration> residuals;
  std::vector<LawResidual> laws;                     ///< for law_segment
  std::optional<std::size_t> law_segment;            ///< the rise or return compared
};

/// Runs the analysis of model.dynamics (which must be set).
/// @throws io::InputError if a given preload is too small for any rate (the sizing cannot hold).
CamDynamics analyse_dynamics(const CamModel& model);

/// The rigid follower on its spring: sqrt(k / M) [rad/s] (0 without a spring).
double spring_natural_frequency(const gearkit::cam::FollowerTrain& train);

}  // namespace gearkit::plugins::cam
