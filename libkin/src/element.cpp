#include <gearkit/kin/element.hpp>

namespace gearkit::kin {

ElementError::ElementError(std::string field, const std::string& message)
    : std::invalid_argument(message), field_(std::move(field)) {}
ElementError::~ElementError() = default;

}  // namespace gearkit::kin
