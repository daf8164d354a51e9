#pragma once
// Error policy: bad input is reported as one line "where: expected ..., found ..." and exit status 2.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gearkit::io {

/// Bad input from a person: a model file, an option, a path. The message is one complete
/// line that names the place (file:line:column or --option), what was expected and what was
/// found. The CLI prints it to stderr and exits with status 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message);
  ~InputError() override;
};

/// A position in a source file, 1-based as editors show it. line == 0 means "whole file".
struct SourceMark {
  std::string file;
  int line = 0;
  int column = 0;
};

/// A value quoted for a one-line message: 'value', at most `max_chars` characters of it (then
/// "..."), with line breaks, tabs and other control characters shown as \n, \t, \xNN.
std::string quote(std::string_view value, std::size_t max_chars = 60);

/// "file:line:column" (or just "file" when the line is unknown).
std::string to_string(const SourceMark& mark);

/// Throws InputError("<mark>: <message>").
[[noreturn]] void fail_at(const SourceMark& mark, std::string_view message);

/// Throws InputError("option '<option>': <message>"); pass the option as typed ("--dxf").
[[noreturn]] void fail_option(std::string_view option, std::string_view message);

}  // namespace gearkit::io
