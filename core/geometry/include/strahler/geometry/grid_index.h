#pragma once

#include "strahler/geometry/aabb.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace strahler::geometry {

/// Uniform grid of item ids over fixed bounds, for "what is near this box" queries in
/// O(items nearby). Items are registered by their bounding box; a query may report an item
/// more than once when it spans several cells.
class GridIndex {
public:
  GridIndex() = default;
  /// A grid covering `bounds` with square cells of side `cellSize` (> 0), at most
  /// `maxCells` cells (the side grows to respect it).
  GridIndex(const Aabb& bounds, double cellSize, std::size_t maxCells = 1u << 22) {
    origin_ = bounds.min;
    const Vec2 size = bounds.size();
    cellSize_ = std::max(cellSize, 1e-9);
    for (;;) {
      nx_ = static_cast<int>(std::floor(size.x / cellSize_)) + 1;
      ny_ = static_cast<int>(std::floor(size.y / cellSize_)) + 1;
      if (static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) <= maxCells)
        break;
      cellSize_ *= 1.5;
    }
    cells_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  }

  /// Side of a cell.
  double cellSize() const noexcept { return cellSize_; }

  /// Registers `id` in every cell its box touches (clamped to the grid).
  void insert(const Aabb& box, std::uint32_t id) {
    forEachCell(box, [&](std::vector<std::uint32_t>& cell) { cell.push_back(id); });
  }

  /// Registers ids 0 .. count−1 by their boxes boxOf(id), as many insert() calls but each
  /// cell's list allocated once at its final size (a counting pass first).
  template <class BoxOf> void insertAll(std::uint32_t count, BoxOf&& boxOf) {
    std::vector<std::uint32_t> sizes(cells_.size(), 0);
    for (std::uint32_t id = 0; id < count; ++id)
      forEachCellIndex(boxOf(id), [&](std::size_t c) { ++sizes[c]; });
    for (std::size_t c = 0; c < cells_.size(); ++c)
      cells_[c].reserve(cells_[c].size() + sizes[c]);
    for (std::uint32_t id = 0; id < count; ++id)
      insert(boxOf(id), id);
  }

  /// The ids registered in the cell that holds p (clamped to the grid), in insertion order.
  const std::vector<std::uint32_t>& cellAt(Vec2 p) const noexcept {
    return cells_[index(cellX(p.x), cellY(p.y))];
  }

  /// Number of cells.
  std::size_t cellCount() const noexcept { return cells_.size(); }
  /// Index (below cellCount()) of the cell that holds p (clamped to the grid).
  std::size_t cellIndexAt(Vec2 p) const noexcept { return index(cellX(p.x), cellY(p.y)); }
  /// The ids registered in cell `index`, in insertion order.
  const std::vector<std::uint32_t>& cell(std::size_t index) const noexcept { return cells_[index]; }
  /// The box of cell `index` (points clamped into an edge cell may lie outside it).
  Aabb cellBox(std::size_t index) const noexcept {
    const auto x = static_cast<double>(index % static_cast<std::size_t>(nx_));
    const auto y = static_cast<double>(index / static_cast<std::size_t>(nx_));
    const Vec2 min{origin_.x + x * cellSize_, origin_.y + y * cellSize_};
    return Aabb{min, {min.x + cellSize_, min.y + cellSize_}};
  }
  /// Calls fn(id) for every id whose cells meet `box`; stops early if fn returns false.
  template <class Fn> bool query(const Aabb& box, Fn&& fn) const {
    int x0, y0, x1, y1;
    cellRange(box, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (std::uint32_t id : cells_[index(x, y)])
          if (!fn(id))
            return false;
    return true;
  }

private:
  int cellX(double x) const noexcept {
    return std::clamp(static_cast<int>(std::floor((x - origin_.x) / cellSize_)), 0, nx_ - 1);
  }
  int cellY(double y) const noexcept {
    return std::clamp(static_cast<int>(std::floor((y - origin_.y) / cellSize_)), 0, ny_ - 1);
  }
  std::size_t index(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(x);
  }
  void cellRange(const Aabb& box, int& x0, int& y0, int& x1, int& y1) const noexcept {
    x0 = cellX(box.min.x);
    y0 = cellY(box.min.y);
    x1 = cellX(box.max.x);
    y1 = cellY(box.max.y);
  }
  template <class Fn> void forEachCellIndex(const Aabb& box, Fn&& fn) const {
    int x0, y0, x1, y1;
    cellRange(box, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        fn(index(x, y));
  }
  template <class Fn> void forEachCell(const Aabb& box, Fn&& fn) {
    forEachCellIndex(box, [&](std::size_t c) { fn(cells_[c]); });
  }

  Vec2 origin_{};
  double cellSize_ = 1.0;
  int nx_ = 1;
  int ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_{1};
};

} // namespace strahler::geometry
