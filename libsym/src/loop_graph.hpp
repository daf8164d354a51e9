#pragma once
// The joint graph of a mechanism (links as nodes, revolute, prismatic and pin-in-slot joints as
// edges) and its simple cycles, the loops a course closes by hand.
#include <gearkit/kin/model.hpp>

#include <vector>

namespace gearkit::sym::detail {

struct JointEdge {
  enum class Kind { revolute, prismatic, slot };
  Kind kind = Kind::revolute;
  int constraint = 0;     ///< index in Model::constraints()
  kin::BodyPoint a, b;    ///< revolute: the two points; prismatic/slot: a = slider/pin, b = guide/slot
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  ///< prismatic/slot: in b's frame
  std::string name;
};

/// One step of a loop: along edge `edge`, from body `from` to body `to` (kGround allowed).
struct LoopStep {
  int edge = 0;
  int from = 0, to = 0;
};
using Loop = std::vector<LoopStep>;

/// The joints of the model that close loops.
std::vector<JointEdge> joint_edges(const kin::Model& model);

/// Every simple cycle of the joint graph (at most `limit`), shortest first; each cycle once,
/// walked from its lowest body (the ground first).
std::vector<Loop> simple_loops(const std::vector<JointEdge>& edges, int bodies, std::size_t limit);

}  // namespace gearkit::sym::detail
