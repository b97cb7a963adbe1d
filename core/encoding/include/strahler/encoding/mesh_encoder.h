#pragma once

#include "strahler/base/result.h"
#include "strahler/encoding/mesh.h"

#include <string>

namespace strahler::encoding {

/// Draco settings for mesh tiles.
struct DracoOptions {
  /// Maximum position error in metres, > 0: no decoded coordinate moves more than this
  /// (1 cm by default). The bits are positionBitsFor(extent, maxPositionError − r), with
  /// extent the largest side of the mesh's bounding box and r = (5·extent + largest
  /// |coordinate|)·2^-24 the worst float rounding of Draco's (de)quantisation: 17 bits for a
  /// 1.92 km tile, 19 for a 5 km extent (18 by the formula alone). An error that needs more
  /// than 24 bits, float32's precision (under ~0.8 mm for 1.92 km), is refused (kInvalidInput).
  double maxPositionError = 0.01;
  int normalBits = 10; ///< Octahedral normal quantisation, 1..30.
  int uvBits = 12;     ///< Texture coordinate quantisation, 1..30.
  /// Draco encoder speed 0 (smallest) .. 10 (fastest, sequential: ~4× the bytes). 7 is as
  /// small as 5 for terrain tiles and meets the 2 ms budget of a 65×65 tile (mesh_bench).
  int speed = 7;
};

/// The mesh as a raw Draco bitstream (.drc): POSITION, NORMAL and, when the mesh has uvs,
/// TEX_COORD in Draco's own convention (v up, as in OpenGL: v_drc = 1 − v), the convention
/// Draco's glTF transcoder uses and three.js's DRACOLoader expects. Same mesh and options,
/// same bytes. kInvalidInput for inconsistent arrays, options out of range or an unreachable
/// maxPositionError; kInternal for Draco's errors (never an exception).
base::Result<std::string> encodeDraco(const Mesh& mesh, const DracoOptions& options = {});

/// The mesh as binary glTF 2.0 (.glb) with KHR_draco_mesh_compression (uvs as in the Mesh);
/// its node is translated by (origin.x, 0, −origin.y) so tiles of one world line up side by
/// side. Errors as encodeDraco.
base::Result<std::string> encodeGlb(const Mesh& mesh, const DracoOptions& options = {});

/// Position quantisation bits for an extent of `range` metres and a maximum error of
/// `maxError` metres. Draco rounds to the nearest of 2^b − 1 steps over the range, so its
/// error is half a step: b = ceil(log2(range / (2·maxError) + 1)), clamped to [8, 30]
/// (30 also for a non-positive or non-finite maxError).
int positionBitsFor(double range, double maxError) noexcept;

} // namespace strahler::encoding
