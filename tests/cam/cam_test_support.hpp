#pragma once
// Helpers shared by the cam tests: building programs, running the gearkit executable and the
// ezdxf checker (tests/io/ezdxf_check.py, Debian's /usr/bin/python3 with python3-ezdxf).
#include <gearkit/cam/cam_design.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <numbers>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace gearkit::cam::testing {

inline double rad(double deg) { return deg * std::numbers::pi / 180; }

inline Segment dwell(double from_deg, double to_deg) {
  Segment s;
  s.kind = SegmentKind::dwell;
  s.start = rad(from_deg), s.end = rad(to_deg);
  return s;
}

inline Segment move(SegmentKind kind, double from_deg, double to_deg, Law law, double lift) {
  Segment s;
  s.kind = kind;
  s.start = rad(from_deg), s.end = rad(to_deg);
  s.law = law;
  s.lift = lift;
  return s;
}

/// The OTM 2015 problem 2 program (seed 000_bc94d104a9983772.txt): dwell 0-120 deg, cycloidal rise
/// of 1 rad over 120-180 deg, dwell 180-240 deg, cycloidal return over 240-360 deg.
inline MotionProgram otm2015_program() {
  return MotionProgram({dwell(0, 120), move(SegmentKind::rise, 120, 180, Law::cycloidal, 1.0), dwell(180, 240),
                        move(SegmentKind::fall, 240, 360, Law::cycloidal, 1.0)});
}

/// Cycloidal rise of `lift` over 0-120 deg, dwell to 180, cycloidal return to 300, dwell.
inline MotionProgram rise_dwell_return(double lift, Law law = Law::cycloidal) {
  return MotionProgram({move(SegmentKind::rise, 0, 120, law, lift), dwell(120, 180),
                        move(SegmentKind::fall, 180, 300, law, lift), dwell(300, 360)});
}

inline Follower translating(Contact contact, double roller = 0, double offset = 0) {
  Follower f;
  f.motion = FollowerMotion::translating;
  f.contact = contact;
  f.roller_radius = roller;
  f.offset = offset;
  return f;
}

inline Follower oscillating(Contact contact, double pivot, double arm, double roller = 0, double face_offset = 0) {
  Follower f;
  f.motion = FollowerMotion::oscillating;
  f.contact = contact;
  f.pivot_distance = pivot;
  f.arm_length = arm;
  f.roller_radius = roller;
  f.face_offset = face_offset;
  return f;
}

struct RunResult {
  int status = -1;
  std::string output;  ///< stdout
  std::string errors;  ///< stderr
};

inline std::filesystem::path scratch_dir();

/// Runs a shell command, capturing stdout and stderr separately (a plugin host warning on stderr
/// must not spoil the JSON on stdout).
inline RunResult run(const std::string& command) {
  RunResult r;
  static int counter = 0;
  // Process id in the name: ctest may run several test processes at once.
  const std::filesystem::path err =
      scratch_dir() / ("stderr-" + std::to_string(getpid()) + "-" + std::to_string(++counter) + ".txt");
  FILE* pipe = popen((command + " 2>'" + err.string() + "'").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  {
    std::ifstream in(err);
    r.errors.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::filesystem::remove(err);
  return r;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

inline std::filesystem::path scratch_dir() {
  // One folder per process: ctest runs several test processes at once.
  auto dir = std::filesystem::path(GEARKIT_BINARY_DIR) / "test-scratch" / ("cam-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs the ezdxf checker and returns its JSON verdict ({"read_error": ...} if it did not run).
inline nlohmann::json ezdxf_check(const std::filesystem::path& dxf, const std::string& extra = "") {
  const RunResult r = run(std::string("/usr/bin/python3 ") + GEARKIT_SOURCE_DIR + "/tests/io/ezdxf_check.py " +
                          quoted(dxf) + " " + extra);
  if (r.output.empty()) return {{"read_error", r.errors}};
  const auto brace = r.output.rfind("\n{");
  try {
    return nlohmann::json::parse(brace == std::string::npos ? r.output : r.output.substr(brace + 1));
  } catch (const nlohmann::json::exception&) {
    return {{"read_error", r.output}};
  }
}

inline std::string gearkit() { return std::string("'") + GEARKIT_EXE + "' cam "; }

}  // namespace gearkit::cam::testing
