#pragma once
// The gear-pair file of `gearkit gear pair.yaml` (docs/rating.md): geometry, tooling, materials
// and load of one stage in YAML, read with libio's MapReader (units, file:line:column errors).
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/error.hpp>

#include <map>
#include <optional>
#include <string>

namespace gearkit::plugins::gear {

struct PairFile {
  gearkit::gear::GearPairInput geometry;
  std::optional<gearkit::gear::RatingInput> rating;  ///< when the file has a `load:` section
  /// Where each GearPairInput / RatingInput field was written, to report their errors there.
  std::map<std::string, io::SourceMark> marks;
  io::SourceMark file_mark;  ///< the document itself, for fields the file does not set
};

/// Reads a pair file. @throws io::InputError with file:line:column for malformed or out-of-range
/// values, unknown keys, unknown materials or factors, and spectrum rows whose shares do not add up to 1.
PairFile read_pair_file(const std::string& path);

/// The root rating's upper allowances A_sne of a pair file with a grade and no allowance1/2: those
/// of ISO/TR 10064-2 for its grade (as `--quality` gives them), written into `rating.A_sne`; left
/// as they are otherwise. @throws io::InputError at the file's `quality` when they cannot be found.
void grade_allowances(const PairFile& file, const gearkit::gear::GearPairResult& table, gearkit::gear::RatingInput& rating);

/// The place to report a GeometryError / RatingError field of a pair file.
io::SourceMark mark_for_field(const PairFile& file, const std::string& field);

}  // namespace gearkit::plugins::gear
