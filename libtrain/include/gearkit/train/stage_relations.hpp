#pragma once
// Willis' equation of each simple stage, in the members a course names: the planets of a stage
// are eliminated and the relation among its central members and its arm is written as the exam
// writes it, tau w_in + (1 - tau) w_arm - w_out = 0 with tau = (w_out - w_arm)/(w_in - w_arm),
// the ratio with the arm held still. A fixed-axis pair is a stage whose arm is the ground:
// tau w_in - w_out = 0.
#include <gearkit/train/model.hpp>
#include <gearkit/train/rational.hpp>

#include <string>
#include <vector>

namespace gearkit::train {

struct StageRelation {
  MemberId input = ground, output = ground, arm = ground;
  Rational tau;                ///< (w_out - w_arm)/(w_in - w_arm)
  std::vector<MeshId> meshes;  ///< the stage's meshes
};

/// One relation per stage and per central member after the first. Meshes joined through a
/// planet form one stage; a mesh between two members on fixed axes is a stage of its own.
/// @param order the user's velocity vector: of a stage's central members, the one that comes
///        first in it is the input (members not in it follow, in model order).
/// @returns the relations in mesh order; none for a stage with a single central member.
std::vector<StageRelation> stage_relations(const TrainModel& model, const std::vector<MemberId>& order);

/// "-2/5 w_1 + 7/5 w_b - w_45 = 0" (terms in the order input, arm, output; zero terms dropped).
std::string stage_relation_text(const TrainModel& model, const StageRelation& relation);

}  // namespace gearkit::train
