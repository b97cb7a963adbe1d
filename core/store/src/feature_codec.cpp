#include "feature_codec.h"

#include "world_proto.h"

#include <cmath>
#include <string>

namespace strahler::store::detail {
namespace {

using geometry::Vec2;

void encodeLine(const std::vector<Vec2>& lonLat, const std::vector<Vec2>& local,
                v1::Polyline& out) {
  for (const Vec2 p : lonLat) {
    out.add_lon(p.x);
    out.add_lat(p.y);
  }
  for (const Vec2 p : local) {
    out.add_x(p.x);
    out.add_y(p.y);
  }
}

class FeatureDecoder {
public:
  explicit FeatureDecoder(std::string_view name) : name_(name) {}

  base::Status lonLat(Vec2 p, const std::string& where) const {
    if (!(std::abs(p.x) <= 180.0 && std::abs(p.y) <= 90.0))
      return corruptError(name_, where + " has a (lon, lat) that is not in degrees");
    return base::Ok{};
  }

  base::Status local(Vec2 p, const std::string& where) const {
    if (!(std::isfinite(p.x) && std::isfinite(p.y)))
      return corruptError(name_, where + " has a non-finite local position");
    return base::Ok{};
  }

  base::Status positive(bool has, double value, const std::string& what,
                        std::optional<double>& out) const {
    if (!has)
      return base::Ok{};
    if (!(std::isfinite(value) && value > 0.0))
      return corruptError(name_, what + " is not a finite number > 0");
    out = value;
    return base::Ok{};
  }

  base::Status line(const v1::Polyline& m, const std::string& where, std::vector<Vec2>& lonLats,
                    std::vector<Vec2>& points) const {
    const int n = m.lon_size();
    if (n < 2 || m.lat_size() != n || m.x_size() != n || m.y_size() != n)
      return corruptError(name_, where + " has columns of " + std::to_string(n) + ", " +
                                     std::to_string(m.lat_size()) + ", " +
                                     std::to_string(m.x_size()) + " and " +
                                     std::to_string(m.y_size()) +
                                     " values; a line needs the same number, at least 2");
    for (int i = 0; i < n; ++i) {
      const std::string point = where + " point " + std::to_string(i);
      const Vec2 ll{m.lon(i), m.lat(i)};
      const Vec2 p{m.x(i), m.y(i)};
      STRAHLER_RETURN_IF_ERROR(lonLat(ll, point));
      STRAHLER_RETURN_IF_ERROR(local(p, point));
      lonLats.push_back(ll);
      points.push_back(p);
    }
    return base::Ok{};
  }

  base::Result<input::Features> run(const v1::Features& m) const {
    input::Features out;
    for (int i = 0; i < m.mountains_size(); ++i) {
      const v1::Mountain& s = m.mountains(i);
      const std::string where = "feature mountain " + std::to_string(i);
      if (!(s.has_lon() && s.has_lat() && s.has_x() && s.has_y()))
        return corruptError(name_, where + " lacks its position");
      input::MountainFeature mountain;
      mountain.lonLat = {s.lon(), s.lat()};
      mountain.position = {s.x(), s.y()};
      STRAHLER_RETURN_IF_ERROR(lonLat(mountain.lonLat, where));
      STRAHLER_RETURN_IF_ERROR(local(mountain.position, where));
      STRAHLER_RETURN_IF_ERROR(
          positive(s.has_elevation(), s.elevation(), where + " elevation", mountain.elevation));
      STRAHLER_RETURN_IF_ERROR(
          positive(s.has_radius(), s.radius(), where + " radius", mountain.radius));
      out.mountains.push_back(mountain);
    }
    for (int i = 0; i < m.ridges_size(); ++i) {
      const v1::Ridge& s = m.ridges(i);
      const std::string where = "feature ridge " + std::to_string(i);
      input::RidgeFeature ridge;
      STRAHLER_RETURN_IF_ERROR(line(s.line(), where, ridge.lonLat, ridge.line));
      STRAHLER_RETURN_IF_ERROR(
          positive(s.has_elevation(), s.elevation(), where + " elevation", ridge.elevation));
      out.ridges.push_back(std::move(ridge));
    }
    for (int i = 0; i < m.rivers_size(); ++i) {
      const v1::River& s = m.rivers(i);
      input::RiverFeature river;
      STRAHLER_RETURN_IF_ERROR(
          line(s.line(), "feature river " + std::to_string(i), river.lonLat, river.line));
      river.name = s.name();
      out.rivers.push_back(std::move(river));
    }
    return out;
  }

private:
  std::string_view name_;
};

} // namespace

void encodeFeatures(const input::Features& features, v1::Features& out) {
  for (const input::MountainFeature& m : features.mountains) {
    v1::Mountain& s = *out.add_mountains();
    s.set_lon(m.lonLat.x);
    s.set_lat(m.lonLat.y);
    s.set_x(m.position.x);
    s.set_y(m.position.y);
    if (m.elevation)
      s.set_elevation(*m.elevation);
    if (m.radius)
      s.set_radius(*m.radius);
  }
  for (const input::RidgeFeature& r : features.ridges) {
    v1::Ridge& s = *out.add_ridges();
    encodeLine(r.lonLat, r.line, *s.mutable_line());
    if (r.elevation)
      s.set_elevation(*r.elevation);
  }
  for (const input::RiverFeature& r : features.rivers) {
    v1::River& s = *out.add_rivers();
    encodeLine(r.lonLat, r.line, *s.mutable_line());
    s.set_name(r.name);
  }
}

base::Result<input::Features> decodeFeatures(const v1::Features& message, std::string_view name) {
  return FeatureDecoder(name).run(message);
}

} // namespace strahler::store::detail
