#include <gearkit/io/json_writer.hpp>

#include <fmt/compile.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <charconv>
#include <cmath>
#include <iterator>

namespace gearkit::io {

void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  std::size_t run = 0;  // start of the characters that need no escape, appended at once
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    if (u >= 0x20 && s[i] != '"' && s[i] != '\\') continue;
    out.append(s.substr(run, i - run));
    run = i + 1;
    switch (s[i]) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default: fmt::format_to(std::back_inserter(out), "\\u{:04x}", u);
    }
  }
  out.append(s.substr(run));
  out += '"';
}

namespace {

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Exactly eight digits of n < 10^8 ending at `end`, in 32-bit arithmetic.
void write_eight_digits(char* end, std::uint32_t n) {
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t pair = (n % 100) * 2;
    n /= 100;
    *--end = kPairs[pair + 1];
    *--end = kPairs[pair];
  }
}

// The decimal digits of `n` written backwards ending at `end`; returns their start. A
// significand has up to 17 digits: the low eight are written in one go without a 64-bit
// division per pair.
char* write_digits(char* end, std::uint64_t n) {
  while (n >= 100000000) {
    write_eight_digits(end, static_cast<std::uint32_t>(n % 100000000));
    end -= 8;
    n /= 100000000;
  }
  auto m = static_cast<std::uint32_t>(n);
  while (m >= 100) {
    const std::uint32_t pair = (m % 100) * 2;
    m /= 100;
    *--end = kPairs[pair + 1];
    *--end = kPairs[pair];
  }
  if (m >= 10) {
    *--end = kPairs[m * 2 + 1];
    *--end = kPairs[m * 2];
  } else {
    *--end = static_cast<char>('0' + m);
  }
  return end;
}

}  // namespace

void append_json_number(std::string& out, double v) {
  if (v == 0) {
    out += std::signbit(v) ? "-0.0" : "0.0";
    return;
  }
  // The shortest decimal that reads back as v, from Dragonbox (fmt's implementation: fmt has no
  // public entry point for the digits alone, and its formatted output costs twice as much in a
  // sweep that writes tens of millions of numbers). Laid out as JavaScript and nlohmann::json
  // do: plain for decimal exponents -5 < k <= 17, scientific otherwise.
  const auto dec = fmt::detail::dragonbox::to_decimal(std::abs(v));
  char digits[24];
  char* const digits_end = digits + sizeof digits;
  const char* first = write_digits(digits_end, dec.significand);
  const int n = static_cast<int>(digits_end - first);
  const int k = dec.exponent + n;  // the decimal point after the k-th digit
  char text[48];
  char* p = text;
  if (v < 0) *p++ = '-';
  const auto copy = [&p](const char* from, int count) {
    std::memcpy(p, from, static_cast<std::size_t>(count));
    p += count;
  };
  if (k > 0 && k <= 17) {
    if (k >= n) {
      copy(first, n);
      for (int z = n; z < k; ++z) *p++ = '0';
      copy(".0", 2);
    } else {
      copy(first, k);
      *p++ = '.';
      copy(first + k, n - k);
    }
  } else if (k <= 0 && k > -5) {
    copy("0.", 2);
    for (int z = 0; z < -k; ++z) *p++ = '0';
    copy(first, n);
  } else {
    *p++ = *first;
    if (n > 1) {
      *p++ = '.';
      copy(first + 1, n - 1);
    }
    const int e = std::abs(k - 1);
    *p++ = 'e';
    *p++ = k - 1 < 0 ? '-' : '+';
    char exponent[8];
    const char* e_first = write_digits(exponent + sizeof exponent, static_cast<std::uint64_t>(e));
    if (e < 10) *p++ = '0';
    copy(e_first, static_cast<int>(exponent + sizeof exponent - e_first));
  }
  out.append(text, p);
}


JsonKey::JsonKey(std::string_view name) {
  quoted = ",";
  append_json_string(quoted, name);
  quoted += ':';
}


void JsonWriter::key(std::string_view k) {
  Level& level = levels_[depth_ - 1];
  if (!level.first) *out_ += ',';
  level.first = false;
  level.key_at = out_->size() + 1;  // the key as written, inside its quotes
  append_json_string(*out_, k);
  level.key_length = out_->size() - 1 - level.key_at;
  *out_ += ':';
}

void JsonWriter::open(char bracket, bool array) {
  separate();
  *out_ += bracket;
  if (levels_.size() == depth_) levels_.emplace_back();
  Level& level = levels_[depth_++];
  level.first = true;
  level.array = array;
  level.key_length = 0;
}

void JsonWriter::close(char bracket) {
  --depth_;
  *out_ += bracket;
}

void JsonWriter::begin_object() { open('{', false); }
void JsonWriter::end_object() { close('}'); }
void JsonWriter::begin_array() { open('[', true); }
void JsonWriter::end_array() { close(']'); }

void JsonWriter::note_non_finite() {
  std::string path = prefix_;
  for (std::size_t i = 0; i < depth_; ++i) {
    const Level& level = levels_[i];
    if (level.array) {
      path += "[]";
    } else {
      if (!path.empty() && path.back() != '.') path += '.';
      path.append(*out_, level.key_at, level.key_length);
    }
  }
  if (std::find(non_finite_.begin(), non_finite_.end(), path) == non_finite_.end()) non_finite_.push_back(path);
}

void JsonWriter::non_finite_null() {
  *out_ += "null";
  note_non_finite();
}

void JsonWriter::value(int v) {
  separate();
  fmt::format_to(std::back_inserter(*out_), "{}", v);
}

void JsonWriter::value(bool v) {
  separate();
  *out_ += v ? "true" : "false";
}

void JsonWriter::value(std::string_view s) {
  separate();
  append_json_string(*out_, s);
}

void JsonWriter::raw_value(std::string_view json) {
  separate();
  *out_ += json;
}

void JsonWriter::null() {
  separate();
  *out_ += "null";
}

}  // namespace gearkit::io
