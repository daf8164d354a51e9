#pragma once
// A static constructor that leaves a file behind: the host tests check that plugins it must
// refuse before loading never run any code. The file is $GEARKIT_TEST_MARKER_DIR/<name>.
#include <cstdio>
#include <cstdlib>
#include <string>

#define GEARKIT_TEST_MARKER(NAME)                                             \
  namespace {                                                                 \
  const bool marker_written = [] {                                            \
    if (const char* dir = std::getenv("GEARKIT_TEST_MARKER_DIR")) {           \
      if (std::FILE* f = std::fopen((std::string(dir) + "/" NAME).c_str(), "w")) std::fclose(f); \
    }                                                                         \
    return true;                                                              \
  }();                                                                        \
  }
