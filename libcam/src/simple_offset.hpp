#pragma once
// The offset of an arc spline when it needs no arrangement (internal to libcam): where no arc
// turns inside out, no corner folds and no two pieces of the raw offset come near each other,
// the raw offset -- each arc's concentric arc, each corner's arc about it -- already is the offset
// curve, and CGAL's arrangement (offset_cgal.cpp), which would find exactly that one face, is
// skipped.
#include <gearkit/cam/arc_spline.hpp>

#include <optional>
#include <vector>

namespace gearkit::cam::detail {

/// The raw offset of the closed, counter-clockwise chain `pieces` by `distance` to its left, as a
/// closed counter-clockwise loop; std::nullopt if it may not be simple: an arc would turn inside
/// out, a corner's offsets would overlap (the side it turns towards), a straight piece is
/// present, two pieces that are not neighbours come within 1e-6 of the chain's size of each
/// other (closest points found in closed form), or the loop does not turn counter-clockwise.
std::optional<std::vector<Piece>> simple_raw_offset(const std::vector<Piece>& pieces, double distance);

}  // namespace gearkit::cam::detail
