#include <gearkit/io/error.hpp>

#include <fmt/format.h>

namespace gearkit::io {

InputError::InputError(const std::string& message) : std::runtime_error(message) {}
InputError::~InputError() = default;

std::string to_string(const SourceMark& mark) {
  if (mark.line <= 0) return mark.file;
  return fmt::format("{}:{}:{}", mark.file, mark.line, mark.column);
}

void fail_at(const SourceMark& mark, std::string_view message) {
  throw InputError(fmt::format("{}: {}", to_string(mark), message));
}

void fail_option(std::string_view option, std::string_view message) {
  throw InputError(fmt::format("option '{}': {}", option, message));
}

}  // namespace gearkit::io
