#pragma once
// The load-capacity sections of the `gearkit gear` report: a table of the pair's load and
// factors, a table of both gears, JSON key "rating" (docs/rating.md), and the warnings.
#include <gearkit/gear/rating.hpp>
#include <gearkit/io/report.hpp>

namespace gearkit::plugins::gear {

/// Appends the rating to `report` (tables, notes, warnings, json["rating"]).
void add_rating_report(io::Report& report, const gearkit::gear::RatingInput& input, const gearkit::gear::PairRating& rating);

/// json["rating"] alone (also used by `gearkit train --rate` for each mesh).
nlohmann::json rating_json(const gearkit::gear::RatingInput& input, const gearkit::gear::PairRating& rating);

}  // namespace gearkit::plugins::gear
