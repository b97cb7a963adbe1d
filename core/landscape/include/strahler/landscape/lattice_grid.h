#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace strahler::landscape {

/// A row-major grid of `columns` × `rows` values, node (c, r) at index r · columns + c.
template <class T> struct LatticeGrid {
  int columns = 0;
  int rows = 0;
  std::vector<T> values;

  /// A grid of the given size, every value `fill`.
  static LatticeGrid filled(int columns, int rows, T fill) {
    return {
        columns, rows,
        std::vector<T>(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), fill)};
  }
  /// The index of node (c, r).
  std::size_t at(int c, int r) const noexcept {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(c);
  }
  /// Number of nodes.
  std::size_t size() const noexcept { return values.size(); }
};

} // namespace strahler::landscape
