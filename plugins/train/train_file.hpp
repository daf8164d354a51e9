#pragma once
// Reading a gear train from YAML (format in docs/train.md) into gearkit::train::TrainModel.
#include <gearkit/io/error.hpp>
#include <gearkit/train/model.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gearkit::plugins::train {

/// A condition written in the file's `analysis` section, with its place for messages.
struct WrittenCondition {
  std::string text;  ///< "ring", "5=1" or "1=1500 rpm"
  io::SourceMark mark;
};

/// The `analysis` section: conditions used when the command line gives none.
struct FileAnalysis {
  std::vector<WrittenCondition> fix, couple, input;
  std::optional<WrittenCondition> output;
};

struct TrainFile {
  gearkit::train::TrainModel model;
  FileAnalysis analysis;
};

/// Loads and checks a train file. Meshes without their own `efficiency` get `default_efficiency`.
/// @throws io::InputError naming file:line:column for unreadable or malformed YAML, unknown keys,
///   wrong types, and every gearkit::train::ModelError (placed at the offending entry).
TrainFile load_train_file(const std::string& path, double default_efficiency = 1.0);

}  // namespace gearkit::plugins::train
