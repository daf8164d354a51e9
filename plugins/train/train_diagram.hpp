#pragma once
// The picture of `gearkit train --svg/--dxf`: the train's stick diagram (axial half section in the
// textbooks' style: shafts as horizontal lines, gears as vertical bars with their tooth counts,
// internal gears open towards the axis, carriers as brackets holding the planet pins, fixed
// members on hatched ground, every member named) drawn from the train's graph alone, and beside
// it the speed (Kutzbach) diagram of its planetary stages: the peripheral speed v = w r of every
// member against the radius, a ray through the axis for a central member, a line through the
// planet's two pitch-point speeds for a planet.
#include <gearkit/io/drawing.hpp>
#include <gearkit/train/model.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::train {

struct TrainDiagramInput {
  std::string title;                                ///< the train's name, for the title line
  std::vector<gearkit::train::MemberId> fixed;      ///< drawn on hatched ground
  std::vector<gearkit::train::MemberId> inputs;     ///< shafts leaving on the left
  std::optional<gearkit::train::MemberId> output;   ///< shaft leaving on the right
  std::vector<std::pair<gearkit::train::MemberId, gearkit::train::MemberId>> couplings;  ///< shafts leaving, labelled
  /// Speed of every member in `speed_unit` (nullopt: not determined); empty: no speed diagram.
  std::vector<std::optional<double>> speeds;
  std::string speed_unit;                           ///< "rpm", or "x w_sun" for ratios
};

/// Layers: axes (centre lines), gears (one polyline per gear: a closed bar for an external gear,
/// an open bracket for an internal one), gear_labels ("NAME: z = Z", one per gear), shafts,
/// carriers, ground (hatched), member_labels, and for the speed diagram speed_axes, speed_rays
/// (one line per member whose speed is known) and speed_labels ("MEMBER: n = N UNIT").
/// Radii are drawn to one scale (the pitch radius m_n z / (2 cos beta), or z/2 when the module is
/// not given), so meshing bars touch; the drawing's scale is stated under the title.
io::Drawing train_diagram(const gearkit::train::TrainModel& model, const TrainDiagramInput& input);

}  // namespace gearkit::plugins::train
