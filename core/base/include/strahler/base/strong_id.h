#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <limits>

namespace strahler::base {

/// An index that cannot be mixed up with an index of another kind (draco's index types).
template <class Tag> struct StrongId {
  static constexpr std::uint32_t kInvalidValue = std::numeric_limits<std::uint32_t>::max();

  std::uint32_t value = kInvalidValue;

  constexpr StrongId() noexcept = default;
  constexpr explicit StrongId(std::uint32_t v) noexcept : value(v) {}

  /// The id that names nothing (a root's parent, say).
  static constexpr StrongId invalid() noexcept { return StrongId(); }
  /// True unless this is invalid().
  constexpr bool valid() const noexcept { return value != kInvalidValue; }
  /// The id as a container index.
  constexpr std::size_t index() const noexcept { return value; }

  friend constexpr auto operator<=>(StrongId, StrongId) noexcept = default;
};

/// A river node of the network graph.
using NodeId = StrongId<struct NodeTag>;
/// A Voronoi block (one per river node).
using BlockId = StrongId<struct BlockTag>;
/// A terrain or river primitive: an index into WorldData::terrain or WorldData::rivers, as
/// the function taking it says.
using PrimitiveId = StrongId<struct PrimitiveTag>;

} // namespace strahler::base

template <class Tag> struct std::hash<strahler::base::StrongId<Tag>> {
  std::size_t operator()(strahler::base::StrongId<Tag> id) const noexcept {
    return std::hash<std::uint32_t>()(id.value);
  }
};
