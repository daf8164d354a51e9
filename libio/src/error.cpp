#include <gearkit/io/error.hpp>

#include <fmt/format.h>

namespace gearkit::io {

InputError::InputError(const std::string& message) : std::runtime_error(message) {}
InputError::~InputError() = default;

std::string quote(std::string_view value, std::size_t max_chars) {
  std::string out = "'";
  std::size_t shown = 0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    auto c = static_cast<unsigned char>(value[i]);
    bool continuation = (c & 0xC0) == 0x80;  // inside a UTF-8 character: never cut there
    if (!continuation && shown == max_chars) {
      out += "...";
      break;
    }
    if (!continuation) ++shown;
    if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7F) out += fmt::format("\\x{:02X}", c);
    else out += static_cast<char>(c);
  }
  return out + "'";
}

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
