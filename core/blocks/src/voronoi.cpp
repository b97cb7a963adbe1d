#include "voronoi.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace strahler::blocks::detail {
namespace {

using geometry::Aabb;
using geometry::Vec2;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<std::uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using VertexHandle = Delaunay::Vertex_handle;
using FaceHandle = Delaunay::Face_handle;

/// A corner computed by clipping moves onto the Voronoi vertex it stands for when closer than
/// this times the vertex's radius (plus rounding); farther means the circumcentre itself is
/// imprecise (a nearly flat triangle), and the computed corner is kept.
constexpr double kSnapCorner = 1e-6;

/// What building one cell needs besides the triangulation.
struct CellContext {
  const std::vector<Vec2>& sites;
  const std::vector<VoronoiVertex>& vertices;
  const Aabb& frame;
};

/// Stand-in for the circumcentre of a triangle too flat for double precision: far out on the
/// bisector of its longest edge, on the side away from the third corner.
Vec2 farCentre(const std::array<Vec2, 3>& p) {
  std::size_t longest = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (geometry::lengthSquared(p[(k + 1) % 3] - p[k]) >
        geometry::lengthSquared(p[(longest + 1) % 3] - p[longest]))
      longest = k;
  const Vec2 s = p[longest], e = p[(longest + 1) % 3], r = p[(longest + 2) % 3];
  const Vec2 mid = (s + e) * 0.5;
  Vec2 out = geometry::perpendicular(e - s);
  if (geometry::dot(out, r - mid) > 0.0)
    out = out * -1.0;
  return mid + out * 1e6;
}

/// Circumcentre of a triangle, computed relative to its first corner for precision.
Vec2 circumcentre(const std::array<Vec2, 3>& p) {
  const Vec2 ab = p[1] - p[0], ac = p[2] - p[0];
  const double d = 2.0 * geometry::cross(ab, ac);
  const double lb = geometry::lengthSquared(ab), lc = geometry::lengthSquared(ac);
  const Vec2 u{(ac.y * lb - ab.y * lc) / d, (ab.x * lc - ac.x * lb) / d};
  if (d == 0.0 || !std::isfinite(u.x) || !std::isfinite(u.y))
    return farCentre(p);
  return p[0] + u;
}

void triangulate(Delaunay& dt, const std::vector<Vec2>& sites) {
  std::vector<std::pair<Kernel::Point_2, std::uint32_t>> points;
  points.reserve(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    points.emplace_back(Kernel::Point_2(sites[i].x, sites[i].y), static_cast<std::uint32_t>(i));
  dt.insert(points.begin(), points.end()); // spatially sorted, deterministic
}

/// One Voronoi vertex per finite face, in the order of their (rotated) site triples; each
/// face's info becomes its vertex index.
std::vector<VoronoiVertex> numberFaces(const Delaunay& dt, const std::vector<Vec2>& sites) {
  struct Entry {
    std::array<std::uint32_t, 3> ids; // counter-clockwise, smallest first
    FaceHandle face;
  };
  std::vector<Entry> entries;
  entries.reserve(dt.number_of_faces());
  for (FaceHandle f : dt.finite_face_handles()) {
    std::array<std::uint32_t, 3> ids{f->vertex(0)->info(), f->vertex(1)->info(),
                                     f->vertex(2)->info()};
    std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
    entries.push_back({ids, f});
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.ids < b.ids; });
  std::vector<VoronoiVertex> vertices(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const auto& ids = entries[k].ids;
    entries[k].face->info() = static_cast<std::uint32_t>(k);
    VoronoiVertex& v = vertices[k];
    v.position = circumcentre({sites[ids[0]], sites[ids[1]], sites[ids[2]]});
    v.sites = {NodeId(ids[0]), NodeId(ids[1]), NodeId(ids[2])};
    v.radius = geometry::distance(v.position, sites[ids[0]]);
  }
  return vertices;
}

/// The faces around v, counter-clockwise.
std::vector<FaceHandle> facesAround(const Delaunay& dt, VertexHandle v) {
  std::vector<FaceHandle> faces;
  auto circulator = dt.incident_faces(v), done = circulator;
  do {
    faces.push_back(circulator);
  } while (++circulator != done);
  return faces;
}

/// The nodes before and after v in face f, counter-clockwise: the cell edges entering and
/// leaving f's Voronoi vertex separate v's cell from these two.
std::pair<VertexHandle, VertexHandle> sidesOf(FaceHandle f, VertexHandle v) {
  const int i = f->index(v);
  return {f->vertex(Delaunay::ccw(i)), f->vertex(Delaunay::cw(i))};
}

/// The exact cell from the circumcentres of the faces around v, when they are all finite
/// and inside the frame (the usual case); empty otherwise.
TaggedRing chainCell(const Delaunay& dt, const std::vector<FaceHandle>& faces, VertexHandle v,
                     const CellContext& ctx) {
  TaggedRing cell;
  for (FaceHandle f : faces) {
    if (dt.is_infinite(f))
      return {};
    const VoronoiVertex& corner = ctx.vertices[f->info()];
    if (!ctx.frame.contains(corner.position))
      return {};
    cell.push(corner.position, f->info(), NodeId(sidesOf(f, v).second->info()));
  }
  return cell;
}

/// True when a corner computed at p can stand for Voronoi vertex `vertex`.
bool closeEnough(const VoronoiVertex& vertex, Vec2 p) {
  const double rounding =
      64.0 * std::numeric_limits<double>::epsilon() * (std::abs(p.x) + std::abs(p.y));
  return geometry::distance(vertex.position, p) <= kSnapCorner * vertex.radius + rounding;
}

/// The Voronoi vertex at corner p of v's cell between the edges facing `before` and `after`:
/// the face with exactly these sides or, when `exact` is false (cocircular sites make the
/// Delaunay choice arbitrary), a face sharing one of them; kNoVertex if none lies at p.
std::uint32_t findVertex(const Delaunay& dt, const std::vector<FaceHandle>& faces, VertexHandle v,
                         NodeId before, NodeId after, Vec2 p, bool exact, const CellContext& ctx) {
  for (FaceHandle f : faces) {
    if (dt.is_infinite(f))
      continue;
    const auto [in, out] = sidesOf(f, v);
    const bool inMatch = NodeId(in->info()) == before, outMatch = NodeId(out->info()) == after;
    if ((exact ? inMatch && outMatch : inMatch || outMatch) &&
        closeEnough(ctx.vertices[f->info()], p))
      return f->info();
  }
  return kNoVertex;
}

/// Tags corner k of a cell clipped from half-planes with its Voronoi vertex, if it is one,
/// and moves it exactly onto the vertex.
void tagCorner(TaggedRing& cell, std::size_t k, const std::vector<FaceHandle>& faces,
               const Delaunay& dt, VertexHandle v, const CellContext& ctx) {
  const NodeId before = cell.neighbours[(k + cell.size() - 1) % cell.size()];
  const NodeId after = cell.neighbours[k];
  if (!before.valid() || !after.valid())
    return;
  std::uint32_t found = findVertex(dt, faces, v, before, after, cell.points[k], true, ctx);
  if (found == kNoVertex)
    found = findVertex(dt, faces, v, before, after, cell.points[k], false, ctx);
  if (found == kNoVertex)
    return;
  cell.points[k] = ctx.vertices[found].position;
  cell.vertices[k] = found;
}

/// The cell as the frame cut by the bisector of v and each Delaunay neighbour: robust for
/// unbounded cells and for cells whose circumcentres are far away (and so imprecise).
TaggedRing clippedCell(const Delaunay& dt, const std::vector<FaceHandle>& faces, VertexHandle v,
                       const CellContext& ctx) {
  TaggedRing cell = boxRing(ctx.frame);
  const Vec2 site = ctx.sites[v->info()];
  for (FaceHandle f : faces) {
    const VertexHandle w = sidesOf(f, v).second;
    if (dt.is_infinite(w))
      continue;
    const Vec2 other = ctx.sites[w->info()];
    clipHalfPlane(cell, (site + other) * 0.5, other - site, NodeId(w->info()));
  }
  for (std::size_t k = 0; k < cell.size(); ++k)
    tagCorner(cell, k, faces, dt, v, ctx);
  return cell;
}

/// The cell of the site at vertex v, clipped to the frame.
TaggedRing cellOf(const Delaunay& dt, VertexHandle v, const CellContext& ctx) {
  const std::vector<FaceHandle> faces = facesAround(dt, v);
  TaggedRing cell = chainCell(dt, faces, v, ctx);
  if (cell.size() == 0)
    cell = clippedCell(dt, faces, v, ctx);
  dropCoincidentCorners(cell, ctx.vertices);
  return cell;
}

/// Cells of collinear sites (or fewer than three): strips between the bisectors of
/// consecutive sites along their line.
std::vector<TaggedRing> cellsAlongLine(const std::vector<Vec2>& sites, const Aabb& frame) {
  std::vector<std::uint32_t> order(sites.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::pair(sites[a].x, sites[a].y) < std::pair(sites[b].x, sites[b].y);
  });
  std::vector<TaggedRing> cells(sites.size());
  auto clipBisector = [&](TaggedRing& cell, std::uint32_t self, std::uint32_t other) {
    clipHalfPlane(cell, (sites[self] + sites[other]) * 0.5, sites[other] - sites[self],
                  NodeId(other));
  };
  for (std::size_t k = 0; k < order.size(); ++k) {
    TaggedRing cell = boxRing(frame);
    if (k > 0)
      clipBisector(cell, order[k], order[k - 1]);
    if (k + 1 < order.size())
      clipBisector(cell, order[k], order[k + 1]);
    cells[order[k]] = std::move(cell);
  }
  return cells;
}

} // namespace

VoronoiDiagram buildVoronoi(const std::vector<Vec2>& sites, const Aabb& frame) {
  VoronoiDiagram diagram;
  if (sites.size() < 3) {
    diagram.cells = cellsAlongLine(sites, frame);
    return diagram;
  }
  Delaunay dt;
  triangulate(dt, sites);
  if (dt.dimension() < 2) {
    diagram.cells = cellsAlongLine(sites, frame);
    return diagram;
  }
  diagram.vertices = numberFaces(dt, sites);
  std::vector<VertexHandle> handles(sites.size());
  for (VertexHandle v : dt.finite_vertex_handles())
    handles[v->info()] = v;
  const CellContext ctx{sites, diagram.vertices, frame};
  diagram.cells.reserve(sites.size());
  for (VertexHandle v : handles)
    diagram.cells.push_back(cellOf(dt, v, ctx));
  return diagram;
}

} // namespace strahler::blocks::detail
