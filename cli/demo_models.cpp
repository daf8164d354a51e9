#include "demo_models.hpp"

namespace gearkit::cli {

const std::vector<DemoStep>& demo_steps() {
  static const std::vector<DemoStep> steps = {
      // OTM 2015 problem 3 (seed 000_bc94d104a9983772.txt): the modified stage z1 = 10,
      // z2 = 40, m = 9 mm with V-0 profile shift x = +/-0.2353 (4/17) against undercut, at the
      // centre distance a = 225 mm of the reducer.
      {"Gear table: OTM 2015 problem 3, stage with V-0 profile shift", "gear",
       {"--z1", "10", "--z2", "40", "--module", "9", "--x1", "0.2353", "--x2", "-0.2353"}, "gear-table.txt"},
      // Seed 004: two epicyclic stages sharing arm b; ratios for each member held fixed.
      {"Compound epicyclic train: two coupled stages (seed 004)", "train",
       {"{dir}/seed_two_epicyclic_stages.yaml", "--modes"}, "train.txt"},
      {"Cam: cycloidal rise-dwell-return, translating roller follower", "cam",
       {"{dir}/translating_roller_cycloidal.yaml", "--dxf", "{dir}/cam.dxf", "--svg", "{dir}/cam.svg", "--plot",
        "{dir}/cam-motion.svg", "--csv", "{dir}/cam-profile.csv"},
       "cam.txt"},
  };
  return steps;
}

}  // namespace gearkit::cli
