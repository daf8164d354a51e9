#pragma once
// The bevel pair's table and forces as an io::Report: text/md/csv tables and JSON with the
// standards' symbols, the gear's number and a unit suffix (delta1_deg, R_e_mm, d_ae2_mm).
#include <gearkit/gear/bevel.hpp>
#include <gearkit/io/report.hpp>

#include <optional>

namespace gearkit::plugins::gear {

io::Report bevel_report(const gearkit::gear::BevelPairInput& input, const gearkit::gear::BevelPairResult& result,
                        const std::optional<gearkit::gear::BevelForces>& forces);

}  // namespace gearkit::plugins::gear
