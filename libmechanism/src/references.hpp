#pragma once
// Link and point names of a mechanism file resolved against the model read so far.
#include <gearkit/io/error.hpp>
#include <gearkit/kin/joints.hpp>
#include <gearkit/kin/model.hpp>

#include <string>

namespace gearkit::mechanism {

/// The body index of link `name` (kin::kGround for "ground"). @throws io::InputError at `mark`.
int resolve_link(const kin::Model& model, const std::string& name, const io::SourceMark& mark);

/// The body and local coordinates [m] of "link.point". @throws io::InputError at `mark`.
kin::BodyPoint resolve_point(const kin::Model& model, const std::string& text, const io::SourceMark& mark);

}  // namespace gearkit::mechanism
