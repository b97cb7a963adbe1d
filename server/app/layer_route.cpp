#include "layer_route.h"

#include "route_parser.h"

#include "strahler/layers/vegetation_density.h"

#include <charconv>
#include <cmath>

namespace strahler::app {
namespace {

base::Error badLayer(const std::string& why) {
  return base::makeError(base::ErrorCode::kInvalidInput, why);
}

/// A plain decimal number of degrees in [0, max] (or [0, max) when `open`), digits with at
/// most six after a point.
base::Result<double> parseDegrees(const std::string& what, const std::string& text, double max,
                                  bool open) {
  const std::size_t dot = text.find('.');
  const std::string whole = text.substr(0, dot);
  const std::string fraction = dot == std::string::npos ? "" : text.substr(dot + 1);
  const auto digits = [](const std::string& s) {
    return s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (whole.empty() || whole.size() > 3 || !digits(whole) || !digits(fraction) ||
      fraction.size() > 6 || (dot != std::string::npos && fraction.empty()))
    return badLayer(what + " must be a plain decimal number of degrees (e.g. 315 or 22.5)");
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  if (value > max || (open && value == max))
    return badLayer(what + " must be in [0, " + std::to_string(static_cast<int>(max)) +
                    (open ? ")" : "]") + " degrees");
  return value;
}

} // namespace

base::Result<LayerOptions> parseLayerOptions(const std::string& name,
                                             const std::map<std::string, std::string>& query) {
  LayerOptions layer;
  STRAHLER_ASSIGN_OR_RETURN(layer.name, parseLayerName(name));
  const bool hillshade = layer.name == LayerName::kHillshade;
  const bool vegetation = layer.name == LayerName::kVegetation;
  for (const auto& [key, value] : query) {
    if (key == "size")
      continue;
    if ((key == "azimuth" || key == "altitude") && !hillshade)
      return badLayer("'" + key + "' is a parameter of the hillshade layer only, not of " + name);
    if (key == "species" && !vegetation)
      return badLayer("'species' is a parameter of the vegetation layer only, not of " + name);
    if (key != "azimuth" && key != "altitude" && key != "species")
      return badLayer("unknown query parameter '" + key.substr(0, 64) + "' (layer " + name +
                      " takes size" +
                      (hillshade    ? ", azimuth and altitude"
                       : vegetation ? " and species"
                                    : "") +
                      ")");
  }
  if (hillshade) {
    layer.azimuthDeg = kDefaultSunAzimuthDeg;
    layer.altitudeDeg = kDefaultSunAltitudeDeg;
    if (const auto a = query.find("azimuth"); a != query.end()) {
      STRAHLER_ASSIGN_OR_RETURN(layer.azimuthDeg, parseDegrees("azimuth", a->second, 360.0, true));
    }
    if (const auto a = query.find("altitude"); a != query.end()) {
      STRAHLER_ASSIGN_OR_RETURN(layer.altitudeDeg,
                                parseDegrees("altitude", a->second, 90.0, false));
    }
  }
  if (vegetation) {
    if (const auto s = query.find("species"); s != query.end()) {
      // kSpecies itself (not layers::speciesIndex): route parsing links no terrain code.
      layer.species = -1;
      for (std::size_t i = 0; i < layers::kSpecies.size(); ++i)
        if (layers::kSpecies[i].name == s->second)
          layer.species = static_cast<int>(i);
      if (layer.species < 0) {
        std::string known;
        for (const layers::Species& species : layers::kSpecies)
          known += (known.empty() ? "" : ", ") + std::string(species.name);
        return base::makeError(base::ErrorCode::kNotFound, "unknown species '" +
                                                               s->second.substr(0, 64) +
                                                               "' (species: " + known + ")");
      }
    }
  }
  return layer;
}

base::Result<TileRequest> parseLayerRoute(const std::string& world,
                                          const std::vector<std::string>& s,
                                          const std::map<std::string, std::string>& query) {
  TileRequest request;
  STRAHLER_ASSIGN_OR_RETURN(request.options.layer, parseLayerOptions(s[3], query));
  const bool local = s.size() == 8;
  if (local && s[4] != "local")
    return badLayer("layer tiles are layers/{name}/{z}/{x}/{y}.png (Web Mercator) or "
                    "layers/{name}/local/{z}/{x}/{y}.png");
  const std::size_t at = local ? 5 : 4;
  STRAHLER_ASSIGN_OR_RETURN(request.tile,
                            parseZxy(std::span(s).subspan(at, 3), ".png", "a layer tile"));
  if (const auto q = query.find("size"); q != query.end()) {
    auto v = parseDecimal(q->second, 4);
    if (!v)
      return badLayer("size " + v.error().message);
    const TileSizeRange range = tileSizeRange(TileKind::kLayer);
    if (v.value() < range.min || v.value() > range.max)
      return badLayer("size must be in [" + std::to_string(range.min) + ", " +
                      std::to_string(range.max) + "]");
    request.options.size = v.value() == range.defaultSize ? 0 : static_cast<int>(v.value());
  }
  request.world = world;
  request.format = TileFormat::kLayerPng;
  request.scheme = local ? tiling::SchemeKind::kLocal : tiling::SchemeKind::kWebMercator;
  return request;
}

const char* layerDescription(LayerName name) noexcept {
  switch (name) {
  case LayerName::kSlope:
    return "strahler slope: 16-bit grey PNG, degrees from horizontal = value / 100";
  case LayerName::kAspect:
    return "strahler aspect: 16-bit grey PNG, downhill direction in degrees clockwise from "
           "north = value / 100, 65535 on flat ground";
  case LayerName::kIllumination:
    return "strahler illumination: 8-bit grey PNG, sky-view factor = value / 255 (16 rays of "
           "8 pixels)";
  case LayerName::kHillshade:
    return "strahler hillshade: 8-bit grey PNG, cos(sun, ground normal) = value / 255";
  case LayerName::kHumidity:
    return "strahler humidity: 8-bit grey PNG, humidity 0..1 = value / 255 (rivers' wetness "
           "and a local wetness index)";
  case LayerName::kSediment:
    return "strahler sediment: 8-bit grey PNG, sediment thickness in centimetres";
  case LayerName::kVegetation:
    return "strahler vegetation: 8-bit grey PNG, density of the species 0..1 = value / 255";
  case LayerName::kWater:
    return "strahler water: 8-bit grey PNG, 255 on sea, lakes and rivers, 0 on land";
  }
  return "";
}

std::string layerQuery(const LayerOptions& layer) {
  if (layer.name == LayerName::kVegetation && layer.species != 0)
    return "?species=" +
           std::string(layers::kSpecies[static_cast<std::size_t>(layer.species)].name);
  if (layer.name == LayerName::kHillshade &&
      (layer.azimuthDeg != kDefaultSunAzimuthDeg || layer.altitudeDeg != kDefaultSunAltitudeDeg)) {
    char number[32];
    std::string q = "?azimuth=";
    q.append(number, std::to_chars(number, number + sizeof number, layer.azimuthDeg,
                                   std::chars_format::fixed)
                         .ptr);
    q += "&altitude=";
    q.append(number, std::to_chars(number, number + sizeof number, layer.altitudeDeg,
                                   std::chars_format::fixed)
                         .ptr);
    return q;
  }
  return "";
}

} // namespace strahler::app
