#pragma once
// YAML readers of the load-capacity input shared by gear-pair files and train files (one reader
// each, so that both accept the same): a gear's material (`materials: gear1:` in a pair file,
// `rating: material:` or a gear's `material:` in a train file) and the accuracy grade
// (`quality:` with `iso1328_edition:`). docs/rating.md, docs/train.md.
#include <gearkit/gear/materials.hpp>
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/yaml_model.hpp>

#include <yaml-cpp/yaml.h>

#include <array>
#include <map>
#include <optional>
#include <string>

namespace gearkit::plugins::gear {

/// Reads the material at `node` of `file`: a named material (`18CrNiMo7-6`,
/// `CLASS:GRADE:HARDNESS`) or a map {class:, grade:, hardness:} and/or a user-defined
/// {name:, sigma_Hlim:, sigma_Flim:, E:, nu:, HB:}; `what` names the node in messages.
/// @throws io::InputError at the file:line:column of the offending value for an unknown name or
///         class, a value out of range, an unknown key, or a material that fails gear::validate.
gearkit::gear::Material read_material(const YAML::Node& node, const std::string& file, const char* what);

/// Reads `quality` (a whole ISO 1328 grade, checked against its edition by the rating) and
/// `iso1328_edition` (2013 or 1995, default 2013) of the mapping `r` into `in`.
/// @throws io::InputError at the key for a value that is not a whole number or not an edition.
void read_accuracy(io::MapReader& r, gearkit::gear::RatingInput& in);

/// Reads the `face_load:` mapping (docs/rating.md, "Face load factor"): model (pinion-shaft |
/// sun), planets, span, offset, shaft_diameter, arrangement (a..e), stiffening, K_prime,
/// torque_share (percent), helix_modification. Keys not given keep `f`'s values.
/// @throws io::InputError at the offending key for a bad value or an unknown key; the
///         consistency of the values is checked by the rating (RatingError "face_load").
void read_face_load(io::MapReader& r, gearkit::gear::FaceLoadInput& f);

/// Reads the oil for scuffing (docs/rating.md, "Scuffing"): fzg_stage (1..14), oil_temperature
/// (deg C), oil_viscosity_100 (mm^2/s), oil_density (kg/dm^3), oil_type (mineral | pao | pag |
/// pag-water-soluble | phosphate-ester | traction), lubrication (dip | spray | immersed),
/// driving_gear (1 | 2), min_safety_scuffing. Keys not given keep `in`'s values; `marks` gets the
/// fields fzg_stage, theta_oil, nu_100, rho_15, S_Smin. Does not call r.finish().
/// @throws io::InputError at the offending key.
void read_scuffing_keys(io::MapReader& r, gearkit::gear::RatingInput& in, std::map<std::string, io::SourceMark>& marks);

/// Reads the rating keys of a gear-pair file from the mapping `r` into `in` (one reader for a pair
/// file's top level and a train mesh's `rating:`; docs/rating.md): quality, iso1328_edition,
/// oil_viscosity, the scuffing keys (read_scuffing_keys), flank_roughness | flank_rz, protuberance, root_roughness, deviations {f_pb,
/// f_falpha, F_betax, f_ma, f_sh, tip_relief}, face_load, min_safety_pitting, min_safety_bending,
/// limited_pitting, optimum_long_life, factors. Keys not given keep `in`'s values; `marks` gets
/// where each RatingInput field was written. Does not call r.finish().
/// @throws io::InputError at the offending key.
void read_rating_keys(io::MapReader& r, gearkit::gear::RatingInput& in, std::map<std::string, io::SourceMark>& marks);

/// Reads the tool of gear `i` (0 or 1) from the mapping `rack1:` or `rack2:` of `r` (keys addendum,
/// dedendum, root_radius: h_aP*, h_fP*, rho_fP*; a key not given keeps `pair`'s rack), or nothing
/// when the key is absent. `marks` gets "tool1"/"tool2".
/// @throws io::InputError at the offending key for a value that is not a number or an unknown key.
std::optional<gearkit::gear::Rack> read_tool(io::MapReader& r, int i, const gearkit::gear::GearPairInput& pair,
                                             std::map<std::string, io::SourceMark>& marks);

/// The upper tooth thickness allowances A_sne (mm, per gear) that ISO/TR 10064-2 gives `grade` of
/// `edition` for the pair, as the inspection computes them: the allowances the root rating's
/// generating shift x_E uses when none is given (one source for inspection and rating).
/// @throws gearkit::gear::GeometryError when the allowances cannot be found for the pair.
std::array<double, 2> upper_allowances_of_grade(const gearkit::gear::GearPairInput& pair, const gearkit::gear::GearPairResult& table,
                                                int grade, gearkit::gear::Iso1328Edition edition);

}  // namespace gearkit::plugins::gear
