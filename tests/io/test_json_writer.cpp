// Tests for gearkit/io/json_writer.hpp: JSON written without a document tree, checked by
// reading it back with nlohmann::json (an independent parser) and strtod.
#include <gearkit/io/json_writer.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace gearkit::io;

namespace {

std::string number(double v) {
  std::string s;
  append_json_number(s, v);
  return s;
}

}  // namespace

// Shortest round trip: every double reads back as itself (strtod), and no shorter decimal does
// the same for the samples tried here (the same significant digits as std::to_chars's shortest
// scientific form, Ryu: an independent implementation).
TEST(JsonWriter, NumbersReadBackExactlyAndShortest) {
  std::uint64_t state = 99;
  for (int i = 0; i < 300000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    double v;
    const std::uint64_t bits = state & 0x7fefffffffffffffULL;  // finite, any exponent
    std::memcpy(&v, &bits, sizeof v);
    if (i % 2) v = -v;
    const std::string text = number(v);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    char shortest[40];
    const auto end = std::to_chars(shortest, shortest + sizeof shortest, v, std::chars_format::scientific).ptr;
    std::string digits_of_ours, digits_of_theirs;  // significant digits only
    for (const char* c = shortest; c != end && *c != 'e'; ++c) if (*c >= '0' && *c <= '9') digits_of_theirs += *c;
    for (std::size_t c = 0; c < text.size() && text[c] != 'e'; ++c) if (text[c] >= '0' && text[c] <= '9') digits_of_ours += text[c];
    const auto trim = [](std::string d) {
      d.erase(0, d.find_first_not_of('0'));
      while (!d.empty() && d.back() == '0') d.pop_back();
      return d;
    };
    ASSERT_EQ(trim(digits_of_ours), trim(digits_of_theirs)) << text << " vs " << std::string(shortest, end);
  }
}

// Plain up to 17 integer digits and down to 0.00001, with a ".0" on integers as nlohmann::json
// writes them; scientific with at least two exponent digits otherwise.
TEST(JsonWriter, NumberLayout) {
  EXPECT_EQ(number(0.1), "0.1");
  EXPECT_EQ(number(3.0), "3.0");
  EXPECT_EQ(number(-250.0), "-250.0");
  EXPECT_EQ(number(0.0), "0.0");
  EXPECT_EQ(number(-0.0), "-0.0");
  EXPECT_EQ(number(1e-5), "0.00001");
  EXPECT_EQ(number(1.5e-6), "1.5e-06");
  EXPECT_EQ(number(123456.789), "123456.789");
  EXPECT_EQ(number(1e16), "10000000000000000.0");
  EXPECT_EQ(number(1e17), "1e+17");
  EXPECT_EQ(number(-2.5e300), "-2.5e+300");
  EXPECT_EQ(number(5e-324), "5e-324");
}

TEST(JsonWriter, DocumentsReadBackAndNonFiniteValuesAreNamed) {
  std::string out;
  JsonWriter w(out);
  w.set_path_prefix("positions[]");
  const JsonKey q("q");
  for (int row = 0; row < 2; ++row) {
    out += row ? "," : "[";
    w.begin_object();
    w.key("input_deg");
    w.value(row * 1.5);
    w.key(q);
    w.begin_object();
    w.key("crank.x_mm");
    w.value(row ? NAN : 2.0);
    w.key("quote\"d");
    w.value("tab\there");
    w.end_object();
    w.key("flags");
    w.begin_array();
    w.value(true);
    w.value(3);
    w.null();
    w.end_array();
    w.end_object();
  }
  out += "]";
  const nlohmann::json j = nlohmann::json::parse(out);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[1]["input_deg"].get<double>(), 1.5);
  EXPECT_EQ(j[0]["q"]["crank.x_mm"].get<double>(), 2.0);
  EXPECT_TRUE(j[1]["q"]["crank.x_mm"].is_null());
  EXPECT_EQ(j[0]["q"]["quote\"d"], "tab\there");
  EXPECT_EQ(j[0]["flags"], nlohmann::json({true, 3, nullptr}));
  ASSERT_EQ(w.non_finite_paths().size(), 1u);
  EXPECT_EQ(w.non_finite_paths()[0], "positions[].q.crank.x_mm");
}
