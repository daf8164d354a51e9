#include "loop_graph.hpp"

#include <gearkit/kin/joints.hpp>

#include <algorithm>
#include <set>

namespace gearkit::sym::detail {

std::vector<JointEdge> joint_edges(const kin::Model& model) {
  std::vector<JointEdge> edges;
  const auto& constraints = model.constraints();
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const kin::Constraint* c = constraints[k].constraint.get();
    JointEdge e;
    e.constraint = static_cast<int>(k);
    e.name = constraints[k].name;
    if (const auto* r = dynamic_cast<const kin::Revolute*>(c)) {
      e.kind = JointEdge::Kind::revolute;
      e.a = r->a();
      e.b = r->b();
    } else if (const auto* p = dynamic_cast<const kin::Prismatic*>(c)) {
      e.kind = JointEdge::Kind::prismatic;
      e.a = p->slider();
      e.b = p->guide();
      e.axis = p->axis_local();
    } else if (const auto* s = dynamic_cast<const kin::PinInSlot*>(c)) {
      e.kind = JointEdge::Kind::slot;
      e.a = s->pin();
      e.b = s->slot();
      e.axis = s->axis_local();
    } else {
      continue;  // drivers and plugin elements close no vector loop
    }
    edges.push_back(e);
  }
  return edges;
}

namespace {

// Node numbering: 0 is the ground, body i is i + 1.
int node(int body) { return body + 1; }
int body_of(int node) { return node - 1; }

struct Search {
  const std::vector<JointEdge>& edges;
  std::vector<std::vector<int>> incident;  // per node: edge indices
  std::size_t limit;
  std::vector<Loop> loops;
  std::set<std::vector<int>> seen;  // sorted edge sets
  std::vector<bool> on_path;
  Loop path;

  int other(int e, int n) const {
    const int a = node(edges[e].a.body), b = node(edges[e].b.body);
    return a == n ? b : a;
  }

  void extend(int start, int at) {
    if (loops.size() >= limit) return;
    for (int e : incident[at]) {
      if (!path.empty() && path.back().edge == e) continue;
      const int next = other(e, at);
      if (next == start && !path.empty()) {
        Loop loop = path;
        loop.push_back({e, body_of(at), body_of(next)});
        std::vector<int> key;
        for (const auto& s : loop) key.push_back(s.edge);
        std::sort(key.begin(), key.end());
        if (seen.insert(key).second) loops.push_back(loop);
        continue;
      }
      if (next < start || on_path[next]) continue;
      on_path[next] = true;
      path.push_back({e, body_of(at), body_of(next)});
      extend(start, next);
      path.pop_back();
      on_path[next] = false;
    }
  }
};

}  // namespace

std::vector<Loop> simple_loops(const std::vector<JointEdge>& edges, int bodies, std::size_t limit) {
  Search s{edges, std::vector<std::vector<int>>(bodies + 1), limit, {}, {}, std::vector<bool>(bodies + 1), {}};
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int a = node(edges[e].a.body), b = node(edges[e].b.body);
    if (a == b) continue;
    s.incident[a].push_back(static_cast<int>(e));
    s.incident[b].push_back(static_cast<int>(e));
  }
  for (int start = 0; start <= bodies; ++start) {
    s.on_path.assign(bodies + 1, false);
    s.on_path[start] = true;
    s.extend(start, start);
  }
  std::stable_sort(s.loops.begin(), s.loops.end(), [](const Loop& x, const Loop& y) { return x.size() < y.size(); });
  return s.loops;
}

}  // namespace gearkit::sym::detail
