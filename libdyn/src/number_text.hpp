#pragma once
// Numbers in error and warning messages of libdyn: short, with enough digits to find the value
// in the model file.
#include <cstdio>
#include <string>

namespace gearkit::dyn::detail {

inline std::string num(double v, int significant_digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

}  // namespace gearkit::dyn::detail
