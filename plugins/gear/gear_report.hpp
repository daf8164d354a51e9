#pragma once
// The gear table as an io::Report (text/md/csv tables like the OTM 2015 problem 3 solution
// table, JSON with unit-suffixed keys) and the tooth-form drawing as an io::Drawing.
#include <gearkit/gear/gear_pair.hpp>
#include <gearkit/io/drawing.hpp>
#include <gearkit/io/report.hpp>

#include <string>

namespace gearkit::plugins::gear {

io::Report gear_report(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result);

/// `what`: "pair" (both gears in mesh at the working centre distance), "gear1" or "gear2".
io::Drawing gear_drawing(const gearkit::gear::GearPairInput& input, const gearkit::gear::GearPairResult& result,
                         const std::string& what);

}  // namespace gearkit::plugins::gear
