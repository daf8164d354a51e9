#include "train_conditions.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/io/quantity.hpp>

#include <fmt/format.h>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;

namespace {

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

std::string member_list(const gt::TrainModel& model) {
  std::vector<std::string> names;
  for (const auto& m : model.members()) names.push_back(m.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

gt::MemberId parse_member(const gt::TrainModel& model, const std::string& name, const ConditionFail& fail) {
  const std::string n = trim(name);
  if (const auto id = model.find_member(n)) return *id;
  fail(fmt::format("expected a member of the train ({}), found {}", member_list(model), io::quote(n)));
  throw std::logic_error("ConditionFail returned");
}

gt::Condition parse_fix(const gt::TrainModel& model, const std::string& text, const ConditionFail& fail) {
  const gt::MemberId m = parse_member(model, text, fail);
  return gt::Condition{gt::Condition::Kind::fix, m, gt::ground, "fix " + model.member(m).name};
}

gt::Condition parse_couple(const gt::TrainModel& model, const std::string& text, const ConditionFail& fail) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) fail(fmt::format("expected two members as A=B, found {}", io::quote(text)));
  const gt::MemberId a = parse_member(model, text.substr(0, eq), fail);
  const gt::MemberId b = parse_member(model, text.substr(eq + 1), fail);
  if (a == b) fail(fmt::format("expected two different members, found {}", io::quote(text)));
  return gt::Condition{gt::Condition::Kind::couple, a, b,
                       "couple w_" + model.member(a).name + " = w_" + model.member(b).name};
}

ParsedInput parse_input(const gt::TrainModel& model, const std::string& text, const ConditionFail& fail,
                        bool typed_option) {
  const auto eq = text.find('=');
  const gt::MemberId m = parse_member(model, text.substr(0, eq), fail);
  ParsedInput input{gt::Condition{gt::Condition::Kind::input, m, gt::ground, "input " + model.member(m).name},
                    std::nullopt};
  if (eq != std::string::npos) {
    try {
      const std::string speed = trim(text.substr(eq + 1));
      input.speed_rad_s = typed_option ? io::parse_option_quantity_si(speed, io::Quantity::angular_velocity, "")
                                       : io::parse_quantity_si(speed, io::Quantity::angular_velocity, "rpm");
    } catch (const io::QuantityError& e) {
      fail(fmt::format("input speed of {}: {}", io::quote(model.member(m).name), e.what()));
    }
    input.condition.label = "input " + model.member(m).name + " = " + trim(text.substr(eq + 1));
  }
  if (m == gt::ground) fail("expected a moving member as input, found 'ground'");
  return input;
}

std::pair<gt::MemberId, double> parse_member_quantity(const gt::TrainModel& model, const std::string& text,
                                                      io::Quantity quantity, const ConditionFail& fail) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) fail(fmt::format("expected MEMBER=VALUE, found {}", io::quote(text)));
  const gt::MemberId m = parse_member(model, text.substr(0, eq), fail);
  if (m == gt::ground) fail("expected a moving member, found 'ground'");
  try {
    return {m, io::parse_option_quantity_si(trim(text.substr(eq + 1)), quantity, "")};
  } catch (const io::QuantityError& e) {
    fail(e.what());
  }
  throw std::logic_error("ConditionFail returned");
}

}  // namespace gearkit::plugins::train
