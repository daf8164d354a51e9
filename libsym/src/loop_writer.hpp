#pragma once
// Writes the closure equations of one loop in the user's coordinates: each link contributes
// the vector between the two joints the loop passes, as length times cos/sin of the angle the
// course measures; a prismatic joint contributes its displacement along its axis.
#include "loop_graph.hpp"
#include "symbolic_system.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearkit::sym::detail {

class LoopWriter {
 public:
  LoopWriter(const kin::Model& model, const EquationsInput& input, const Eigen::VectorXd& pose, SymbolicSystem& sys);

  /// The rows the loop gives: two (x and y) when every displacement it passes is a coordinate,
  /// one (projection on the normal of the only unknown slide), none when a link's angle is not
  /// a coordinate or more than one slide is unknown.
  std::vector<GiNaC::ex> rows(const Loop& loop) const;
  /// "O1 - P - Q - O2 - O1" from the joint names.
  std::string describe(const Loop& loop) const;
  const std::vector<JointEdge>& edges() const { return edges_; }

 private:
  using Vec = std::array<GiNaC::ex, 2>;
  double body_angle(int body) const;
  /// The world direction angle = zero + sense phi_k + off of coordinate k, as (cos, sin).
  Vec direction(int k, double off) const;
  /// World direction of a local direction beta on `body`, as (cos, sin); nullopt if unknown.
  std::optional<Vec> local_direction(int body, double beta) const;
  std::optional<Vec> body_vector(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const;
  Vec fixed_vector(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const;
  GiNaC::ex length(int body, const Eigen::Vector2d& p, const Eigen::Vector2d& r) const;
  int group_of(int body) const { return group_[static_cast<std::size_t>(body + 1)]; }

  const kin::Model& model_;
  const EquationsInput& input_;
  const Eigen::VectorXd& pose_;
  SymbolicSystem& sys_;
  std::vector<JointEdge> edges_;
  std::vector<int> group_;          // per node (ground 0): angle group
  std::vector<int> group_coord_;    // per group: coordinate giving its angle, -1 none
  std::vector<bool> group_fixed_;   // per group: contains the ground
};

}  // namespace gearkit::sym::detail
