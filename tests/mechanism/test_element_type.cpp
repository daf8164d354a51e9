// Tests for gearkit/mechanism/element_type.hpp: what an element type's read function gets (links
// and points resolved against the model read so far, errors at the key), and where the reader
// puts a builder's kin::ElementError.
#include <gearkit/kin/angle_relation.hpp>
#include <gearkit/mechanism/reader.hpp>

#include <gtest/gtest.h>

namespace gearkit::mechanism {
namespace {

// theta_b = ratio theta_a; a ratio of 0 is refused by the "builder" with an ElementError.
std::unique_ptr<kin::Constraint> read_ratio(ElementReader& reader) {
  const int a = reader.link("a");
  const int b = reader.link_or("b", kin::kGround);
  const kin::BodyPoint p = reader.point("at");
  EXPECT_EQ(p.body, a);
  EXPECT_NEAR(p.local.x(), 0.010, 1e-15);  // 10 mm
  const double ratio = reader.keys().number("ratio");
  if (ratio == 0.0) throw kin::ElementError("ratio", "'ratio': expected a ratio other than 0");
  return std::make_unique<kin::AngleRelation>(std::vector<std::pair<int, double>>{{b, 1.0}, {a, -ratio}}, 0.0, "ratio");
}

const ElementTypeSpec kRatio{"ratio", "theta_b = ratio theta_a", &read_ratio};

std::string model_with(const std::string& element) {
  return "ground: {O: [0, 0]}\nlinks:\n  a: {points: {O: [0, 0], P: [10, 0]}}\n  b: {points: {O: [0, 0]}}\n"
         "joints:\n  - {type: revolute, at: [a.O, ground.O]}\n  - {type: revolute, at: [b.O, ground.O]}\n"
         "elements:\n  - " + element + "\n";
}

Mechanism read(const std::string& text) {
  return read_mechanism(io::load_yaml_text(text, "m.yaml"),
                        [](std::string_view type) { return type == "ratio" ? &kRatio : nullptr; });
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ElementType, ReadFunctionResolvesLinksAndPoints) {
  const Mechanism m = read(model_with("{type: ratio, name: r, a: a, b: b, at: a.P, ratio: 2}"));
  ASSERT_EQ(m.model.constraints().size(), 3u);
  EXPECT_EQ(m.model.constraints()[2].name, "r");
  EXPECT_EQ(m.model.constraints()[2].constraint->kind(), "ratio");
}

TEST(ElementType, ErrorsArePlacedAtTheirKey) {
  EXPECT_EQ(error_of(model_with("{type: ratio, a: c, at: a.P, ratio: 2}")), "m.yaml:9:22: unknown link 'c'");
  EXPECT_EQ(error_of(model_with("{type: ratio, a: a, at: a.Q, ratio: 2}")), "m.yaml:9:29: link 'a' has no point 'Q'");
  // The builder's ElementError lands on the key its field names.
  EXPECT_EQ(error_of(model_with("{type: ratio, a: a, at: a.P, ratio: 0}")),
            "m.yaml:9:41: 'ratio': expected a ratio other than 0");
  // Keys the read function did not ask for are typos.
  EXPECT_NE(error_of(model_with("{type: ratio, a: a, at: a.P, ratio: 2, ratoi: 3}")).find("unknown key 'ratoi'"),
            std::string::npos);
  EXPECT_NE(error_of(model_with("{type: gear_mesh, a: a}")).find("unknown element type 'gear_mesh'"), std::string::npos);
}

TEST(ElementType, TheJointTypesAreBuiltIn) {
  EXPECT_EQ(builtin_joint_types(), (std::vector<std::string>{"revolute", "prismatic", "pin_in_slot", "contact"}));
}

}  // namespace
}  // namespace gearkit::mechanism
