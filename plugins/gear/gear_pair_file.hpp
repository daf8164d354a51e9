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

/// The place to report a GeometryError / RatingError field of a pair file.
io::SourceMark mark_for_field(const PairFile& file, const std::string& field);

}  // namespace gearkit::plugins::gear
