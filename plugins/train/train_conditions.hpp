#pragma once
// Conditions typed by a user (--fix ring, --couple 5=1, --input sun=1500 rpm) or written in a
// train file's `analysis` section, turned into gearkit::train::Condition.
#include <gearkit/io/quantity.hpp>
#include <gearkit/train/kinematics.hpp>
#include <gearkit/train/model.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::plugins::train {

/// Reports a problem with one condition; must throw io::InputError naming its place.
using ConditionFail = std::function<void(std::string_view message)>;

/// The member called `name`. Calls fail (which throws) listing the members when unknown.
gearkit::train::MemberId parse_member(const gearkit::train::TrainModel& model, const std::string& name,
                                      const ConditionFail& fail);

struct ParsedInput {
  gearkit::train::Condition condition;
  std::optional<double> speed_rad_s;  ///< nullopt: "--input sun" (ratios only)
};

gearkit::train::Condition parse_fix(const gearkit::train::TrainModel& model, const std::string& text,
                                    const ConditionFail& fail);
/// "A=B".
gearkit::train::Condition parse_couple(const gearkit::train::TrainModel& model, const std::string& text,
                                       const ConditionFail& fail);
/// "MEMBER=SPEED" or just "MEMBER". `typed_option`: the text is from --input, whose SPEED needs its
/// unit ("sun=1500rpm"; docs/cli.md, "Quantity options"); else from a train file, where a bare
/// SPEED is rpm (docs/train.md).
ParsedInput parse_input(const gearkit::train::TrainModel& model, const std::string& text, const ConditionFail& fail,
                        bool typed_option);

/// "MEMBER=VALUE" of an option (--torque, --power), VALUE a quantity of kind `q` with its unit (a
/// bare number is refused: io::parse_option_quantity_si); returns member and SI value.
std::pair<gearkit::train::MemberId, double> parse_member_quantity(const gearkit::train::TrainModel& model,
                                                                  const std::string& text, io::Quantity quantity,
                                                                  const ConditionFail& fail);

}  // namespace gearkit::plugins::train
