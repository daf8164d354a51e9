#pragma once
// The demo's embedded models and command lines (see docs/demo.md for what they show).
#include <string>
#include <vector>

namespace gearkit::cli {

struct DemoModel {
  std::string file;  ///< written into the demo folder
  std::string text;
};

struct DemoStep {
  std::string title;
  std::string command;            ///< a plugin command
  std::vector<std::string> args;  ///< "{dir}" stands for the demo folder
  std::string report_file;        ///< the step's report is also saved here
};

const std::vector<DemoModel>& demo_models();
const std::vector<DemoStep>& demo_steps();

}  // namespace gearkit::cli
