#pragma once
// `gearkit kin --example NAME`: mechanism files generated at any size.
#include <string>

namespace gearkit::cli {

/// The mechanism file (YAML) of a chain of `loops` four-bar loops: crank 40, coupler 120,
/// rocker 80, ground 100 mm (Norton's crank-rocker), the rocker of loop k being the crank of
/// loop k + 1, ground pivots at x = 100 k mm, drawn at crank angle 0 on the open branch (B
/// above the ground line), driven at the first crank (range 0..360 deg by 1 deg), output the
/// last rocker's angle. 2 loops + 1 links, 3 loops + 1 revolutes: Gruebler 1, no redundancy.
std::string chain_mechanism_yaml(int loops);

/// The file of a named example: "chain:N" (N from 1 to 10000; the largest takes about 2 s and
/// 400 MB to analyse, mostly reading its 4.4 MB of YAML).
/// @throws InputError naming option --example for another name or N out of range.
std::string example_mechanism_yaml(const std::string& name);

}  // namespace gearkit::cli
