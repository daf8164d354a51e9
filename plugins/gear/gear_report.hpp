#pragma once
// The gear table as an io::Report (text/md/csv tables like the OTM 2015 problem 3 solution
// table, JSON with unit-suffixed keys); the drawing is in gear_drawing.hpp.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/io/report.hpp>

#include <string>

namespace gearkit::plugins::gear {

io::Report gear_report(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result);

}  // namespace gearkit::plugins::gear
