#include "demo_models.hpp"

namespace gearkit::cli {

const std::vector<DemoModel>& demo_models() {
  static const std::vector<DemoModel> models = {};
  return models;
}

const std::vector<DemoStep>& demo_steps() {
  // OTM 2015 problem 3, first stage with V-0 profile shift (seed 000_bc94d104a9983772.txt).
  static const std::vector<DemoStep> steps = {
      {"Gear table: OTM 2015 problem 3, first stage", "gear",
       {"--z1", "15", "--z2", "17", "--module", "6", "--x1", "0.2353", "--x2", "-0.2353"}, "gear-table.txt"},
  };
  return steps;
}

}  // namespace gearkit::cli
