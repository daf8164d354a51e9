#include "cam_dynamics.hpp"

#include <gearkit/io/error.hpp>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gearkit::plugins::cam {

namespace gc = gearkit::cam;

namespace {

/// Sizes what is missing (force closure) and settles the damping.
void settle_spring(const CamModel& model, CamDynamics& out) {
  const DynamicsInput& in = *model.dynamics;
  out.train = in.train;
  const bool spring = model.design.follower.closure == gc::Closure::spring;
  if (spring) {
    gc::SizingRequest rq;
    rq.omega = out.sizing_omega, rq.min_force = in.min_force;
    rq.spring_rate = in.spring_rate, rq.damping_ratio = in.damping_ratio;
    if (!in.spring_rate) rq.preload = in.preload;
    gc::SpringSizing s;
    try {
      s = gc::size_spring(model.design, in.train, rq);
    } catch (const std::invalid_argument& e) {
      io::fail_at(in.mark, e.what());
    }
    out.rate_sized = !in.spring_rate, out.preload_sized = !in.preload;
    if (out.rate_sized) out.train.spring_rate = s.spring_rate;
    if (out.preload_sized) out.train.preload = s.preload;
    if (!out.rate_sized && !out.preload_sized) out.needed = s;
  }
  if (in.damping_ratio) out.train.damping = gc::damping_for_ratio(out.train, *in.damping_ratio);
}

void compare_laws(const CamModel& model, CamDynamics& out) {
  const auto& segs = model.design.program.segments();
  double worst = -1;
  for (std::size_t i = 0; i < segs.size(); ++i) {  // the most demanding rise or return: largest L / beta^2
    if (segs[i].kind != gc::SegmentKind::rise && segs[i].kind != gc::SegmentKind::fall) continue;
    const double beta = segs[i].end - segs[i].start, demand = segs[i].lift / (beta * beta);
    if (demand > worst) worst = demand, out.law_segment = i;
  }
  if (!out.law_segment) return;
  const gc::Segment& s = segs[*out.law_segment];
  const double scale = model.design.follower.motion == gc::FollowerMotion::translating ? 1e-3 : 1;
  for (const std::string& name : gc::law_names()) {
    const gc::Law law = *gc::law_from_name(name);
    out.laws.push_back({law, gc::residual_vibration_of_law(law, s.lift * scale, s.end - s.start, out.omega,
                                                          out.flexible->natural_frequency, out.flexible->damping_ratio,
                                                          out.flexible->static_ratio)});
  }
}

}  // namespace

double spring_natural_frequency(const gc::FollowerTrain& train) { return std::sqrt(train.spring_rate / train.mass); }

CamDynamics analyse_dynamics(const CamModel& model) {
  const DynamicsInput& in = *model.dynamics;
  CamDynamics out;
  out.omega = in.design_speed;
  out.sizing_omega = in.design_speed * in.jump_margin;
  settle_spring(model, out);
  const gc::ContactMaterial* material = model.contact ? &model.contact->material : nullptr;
  out.states = gc::dynamics_over_turn(model.design, out.train, out.omega, in.samples, material);
  if (model.design.follower.closure == gc::Closure::spring) {
    out.jump = gc::jump_speed(model.design, out.train, 0, in.jump_search_to);
    out.least_margin = gc::least_contact_margin(model.design, out.train, out.omega, in.min_force);
    if (in.sweep) {
      std::vector<double> speeds;
      for (int k = 0; k <= in.sweep->steps; ++k)
        speeds.push_back(in.sweep->from + (in.sweep->to - in.sweep->from) * k / in.sweep->steps);
      out.sweep = gc::sweep_speeds(model.design, out.train, 0, speeds);  // separation, as the jump speed
    }
  }
  if (out.train.stiffness > 0) {
    out.flexible = gc::flexible_response(model.design, out.train, out.omega, in.samples);
    out.residuals = gc::residual_vibrations(model.design, out.train, *out.flexible);
    compare_laws(model, out);
  }
  return out;
}

}  // namespace gearkit::plugins::cam
