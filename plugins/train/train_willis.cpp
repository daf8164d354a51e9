#include "train_willis.hpp"

#include <gearkit/io/error.hpp>
#include <gearkit/train/stage_relations.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace gearkit::plugins::train {

namespace gt = gearkit::train;

namespace {

std::vector<gt::MemberId> parse_vector(const gt::TrainModel& model, const std::string& text) {
  std::vector<gt::MemberId> out;
  std::stringstream ss(text);
  for (std::string name; std::getline(ss, name, ',');) {
    if (!name.empty() && name.rfind("w_", 0) == 0) name = name.substr(2);  // w_45 as the course writes it
    const auto m = model.find_member(name);
    if (!m || *m == gt::ground)
      io::fail_option("--willis", fmt::format("expected members of the train, found {}", io::quote(name)));
    if (model.is_planet(*m))
      io::fail_option("--willis", fmt::format("expected central members and arms, found the planet {}", io::quote(name)));
    if (std::find(out.begin(), out.end(), *m) != out.end())
      io::fail_option("--willis", fmt::format("member {} appears twice", io::quote(name)));
    out.push_back(*m);
  }
  if (out.empty()) io::fail_option("--willis", "expected a list of members such as 1,b,45,7");
  return out;
}

}  // namespace

void add_willis_in_vector(io::Report& report, const gt::TrainModel& model, const std::string& members) {
  const std::vector<gt::MemberId> u = parse_vector(model, members);
  auto in_u = [&u](gt::MemberId m) { return m == gt::ground || std::find(u.begin(), u.end(), m) != u.end(); };
  std::vector<std::string> names;
  for (gt::MemberId m : u) names.push_back("w_" + model.member(m).name);
  io::Table t{fmt::format("Willis equations in u = {{{}}} (planets eliminated)", fmt::join(names, ", ")),
              {"stage", "tau = (w_out - w_arm)/(w_in - w_arm)", "equation"}, {}};
  nlohmann::json j = nlohmann::json::array();
  std::vector<bool> related(u.size(), false);
  for (const gt::StageRelation& r : gt::stage_relations(model, u)) {
    if (!in_u(r.input) || !in_u(r.output) || !in_u(r.arm)) continue;
    const std::string stage = fmt::format("{} -> {}, arm {}", model.member(r.input).name, model.member(r.output).name,
                                          model.member(r.arm).name);
    const std::string equation = gt::stage_relation_text(model, r);
    t.add_row({stage, gt::to_fraction_and_decimal(r.tau, 4), equation});
    j.push_back({{"input", model.member(r.input).name}, {"output", model.member(r.output).name},
                 {"arm", model.member(r.arm).name}, {"tau", gt::to_fraction_string(r.tau)},
                 {"tau_value", gt::to_double(r.tau)}, {"equation", equation}});
    for (std::size_t k = 0; k < u.size(); ++k)
      if (u[k] == r.input || u[k] == r.output || u[k] == r.arm) related[k] = true;
  }
  for (std::size_t k = 0; k < u.size(); ++k)
    if (!related[k])
      report.warnings.push_back(fmt::format("--willis: no stage relates '{}' to the other members of the vector",
                                            model.member(u[k]).name));
  report.tables.push_back(t);
  report.json["willis_in_vector"] = j;
}

}  // namespace gearkit::plugins::train
