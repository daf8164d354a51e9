// CGAL's approximated_inset_2 on a plain polygon: the independent reference for the arc-spline
// offset in offset_cgal.cpp (the second and last CGAL translation unit of libcam).
#include <gearkit/cam/arc_spline.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/approximated_offset_2.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/exceptions.h>

#include <cmath>
#include <iterator>
#include <list>
#include <string>

namespace gearkit::cam {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using GpsTraits = CGAL::Gps_circle_segment_traits_2<Kernel>;
using OffsetPolygon = GpsTraits::Polygon_2;

Piece piece_of(const GpsTraits::X_monotone_curve_2& cv) {
  Piece p;
  p.x0 = CGAL::to_double(cv.source().x());
  p.y0 = CGAL::to_double(cv.source().y());
  p.x1 = CGAL::to_double(cv.target().x());
  p.y1 = CGAL::to_double(cv.target().y());
  if (cv.is_linear()) return p;
  const auto circle = cv.supporting_circle();
  p.cx = CGAL::to_double(circle.center().x());
  p.cy = CGAL::to_double(circle.center().y());
  const double r = std::sqrt(CGAL::to_double(circle.squared_radius()));
  const bool ccw = cv.orientation() == CGAL::COUNTERCLOCKWISE;
  p.radius = ccw ? r : -r;
  p.sweep = turning_angle(p.x0 - p.cx, p.y0 - p.cy, p.x1 - p.cx, p.y1 - p.cy, ccw ? 1.0 : -1.0);
  return p;
}

}  // namespace

std::vector<std::vector<Piece>> polygon_inset(const std::vector<std::pair<double, double>>& points, double distance,
                                              double eps) {
  const CGAL::Failure_behaviour old_error = CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
  std::vector<std::vector<Piece>> loops;
  try {
    Polygon polygon;
    for (const auto& [x, y] : points) polygon.push_back(Kernel::Point_2(x, y));
    std::list<OffsetPolygon> insets;
    CGAL::approximated_inset_2(polygon, Kernel::FT(distance), eps, std::back_inserter(insets));
    for (const OffsetPolygon& inset : insets) {
      std::vector<Piece> loop;
      for (auto cv = inset.curves_begin(); cv != inset.curves_end(); ++cv) loop.push_back(piece_of(*cv));
      loops.push_back(loop);
    }
  } catch (const CGAL::Failure_exception& error) {
    CGAL::set_error_behaviour(old_error);
    throw GeometryError(std::string("CGAL failed in approximated_inset_2: ") + error.what());
  }
  CGAL::set_error_behaviour(old_error);
  if (loops.empty()) throw GeometryError("the polygon's inset is empty");
  return loops;
}

}  // namespace gearkit::cam
