#include "references.hpp"

#include <gearkit/mechanism/element_type.hpp>

namespace gearkit::mechanism {

int resolve_link(const kin::Model& model, const std::string& name, const io::SourceMark& mark) {
  const auto body = model.body_index(name);
  if (!body) io::fail_at(mark, "unknown link " + io::quote(name));
  return *body;
}

kin::BodyPoint resolve_point(const kin::Model& model, const std::string& text, const io::SourceMark& mark) {
  const auto dot = text.find('.');
  if (dot == std::string::npos) io::fail_at(mark, "expected a point reference 'link.point', found " + io::quote(text));
  const std::string link = text.substr(0, dot), point = text.substr(dot + 1);
  const auto body = model.body_index(link);
  if (!body) io::fail_at(mark, "unknown link " + io::quote(link) + " in " + io::quote(text));
  const kin::Body& b = *body == kin::kGround ? model.ground() : model.bodies()[static_cast<std::size_t>(*body)];
  const auto local = b.point(point);
  if (!local) io::fail_at(mark, "link " + io::quote(link) + " has no point " + io::quote(point));
  return {*body, *local};
}

int ElementReader::link(const std::string& key) {
  return resolve_link(model_, keys_.string(key), keys_.mark(key));
}

int ElementReader::link_or(const std::string& key, int default_body) {
  return keys_.has(key) ? link(key) : default_body;
}

kin::BodyPoint ElementReader::point(const std::string& key) {
  return resolve_point(model_, keys_.string(key), keys_.mark(key));
}

}  // namespace gearkit::mechanism
