#pragma once

#include "strahler/base/result.h"
#include "strahler/input/limits.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace strahler::input {

/// Geographic bounds in degrees: west < east in [-180, 180], south < north in [-90, 90].
struct GeoBounds {
  double west = 0.0;
  double south = 0.0;
  double east = 0.0;
  double north = 0.0;

  /// Exact comparison (round-trip tests, caching).
  bool operator==(const GeoBounds&) const = default;
};

/// What a constraint image controls (the paper's Figure 17).
enum class ConstraintKind {
  kMountainousness, ///< m(p) ∈ [0, 1]: river slopes and ridge steepness (λ).
  kRiverSlope,      ///< River slope, [0, 1] mapped to [slopeMin, slopeMax].
};

/// A constraint image named in params JSON:
/// {"kind": "mountainousness" | "riverSlope", "image": PATH, "bounds": [W, S, E, N]}.
struct ConstraintSource {
  ConstraintKind kind = ConstraintKind::kMountainousness;
  std::string imagePath; ///< As written in the JSON (relative to the params file); not empty.
  GeoBounds bounds;

  /// Exact comparison.
  bool operator==(const ConstraintSource&) const = default;
};

/// At most this many constraint images per world.
inline constexpr std::size_t kMaxConstraints = 16;

/// Which grower builds the river network (issue 30).
enum class NetworkGrower {
  kGrammar, ///< The open grammar of Section 4.2 (network_growth.h), the paper's.
  kDla,     ///< Off-lattice diffusion-limited aggregation (seed 001; dla_growth.h).
};

/// The name of `grower` in params JSON and on the command line: "grammar" or "dla".
const char* growerName(NetworkGrower grower) noexcept;

/// The grower called `name` ("grammar" or "dla"); kInvalidInput naming both otherwise.
base::Result<NetworkGrower> parseGrower(std::string_view name);

/// One species' response curves in params.json, each a trapezoid [rise0, rise1, fall1, fall0]
/// (layers::ResponseCurve): finite, non-decreasing, in [0, 10000].
struct SpeciesCurves {
  std::array<double, 4> sediment{};     ///< C_S of the sediment thickness, m.
  std::array<double, 4> illumination{}; ///< C_I of the sky view, 0 … 1.
  std::array<double, 4> humidity{};     ///< C_H of the humidity, 0 … 1.

  /// Exact comparison.
  bool operator==(const SpeciesCurves&) const = default;
};

/// The species whose curves params.json may set (core/layers' layers::kSpecies names).
inline constexpr const char* kVegetationSpecies[] = {"tree", "bush"};

/// Every knob of the generation method (Génevaux et al. 2013, Sections 4-5), with the
/// defaults used when params.json leaves it out. Lengths in metres, slopes in m/m, angles in
/// degrees; every value must be finite, and the ranges below are enforced by validateParams.
struct Params {
  // --- Network growth (Section 4.2) ---
  double edgeLength = 1000.0; ///< e: length of every river edge, in [50, 20000].
  double sigma = 800.0;       ///< σ: min distance between non-adjacent edges; > e/√2.
  double delta = 300.0;       ///< δ: min distance from an edge to the coast Γ; in [0, 10 e).
  double kappa = 0.6;         ///< κ: max slope between a new node and nearby nodes; (0, 10].
  double zeta = 20.0;         ///< ζ: height window (m) of node selection, ≥ 0; 0 = lowest first.
  double probContinue = 0.2;  ///< Pc: rule 2.1, prolongation; [0, 1]; Pc + Pa + Ps = 1 ± 1e-6.
  double probAsymmetric = 0.7; ///< Pa: rule 2.2, asymmetric Strahler branching; [0, 1].
  double probSymmetric = 0.1;  ///< Ps: rule 2.3, symmetric Strahler branching; [0, 1].
  double branchAngle = 65.0;   ///< Degrees between a branch and its parent's direction; (0, 90].
  double angleJitter = 15.0;   ///< Degrees of random deviation of each new edge; [0, 60].
  /// Rule 1 (fill): children a filling node asks for, 1 or 2 (default 2). 1 prolongs the
  /// river; 2 also branches off at branchAngle, a binary confluence like rule 2.2's. The
  /// paper's 1..5 children over ±80° made 3- to 5-inflow stars and ended rivers early.
  int fillBranches = 2;

  // --- Elevation-increment (mountainousness) law ---
  // A new node is higher than its parent by Δz = e · s · (1 + jitter · u), u ∈ [-1, 1),
  // s = slopeMin + (slopeMax - slopeMin) · m(p), where the mountainousness m(p) ∈ [0, 1]
  // rises with distance to the coast over coastRamp (or comes from a constraint image).
  double slopeMin = 0.004; ///< River slope at m = 0 (plains, beaches); 0 ≤ slopeMin ≤ slopeMax.
  double slopeMax = 0.06;  ///< River slope at m = 1 (mountains); slopeMax < κ.
  double slopeJitter = 0.5;  ///< Relative random spread of Δz, in [0, 1).
  double coastRamp = 8000.0; ///< Distance from the coast over which m(p) rises 0 -> 1; > 0.

  // --- Mouths (Section 4.1) ---
  int maxPriority = 5;                 ///< Priority s of the best placed mouths; [1, 12].
  double mouthSpacing = 3000.0;        ///< Min distance between automatic mouths; > 0.
  double accessibilityRadius = 4000.0; ///< Radius of the land-fraction (concavity) measure; > 0.

  // --- Ridges (Section 5.1) ---
  double lambda = 0.35;            ///< λ: ridge rise per metre from the river nodes, [0, 1].
  double lambdaCoastFactor = 0.25; ///< λ multiplier at the coast (gentle beaches), (0, 1].

  // --- River long profiles ---
  // After growth, every edge's slope follows the stream-power steady state
  // S = s(p) · (A / referenceArea)^−concavity, A the drainage area at its upstream node
  // (km²) and s(p) the elevation law's slope above: steep headwaters, gentle lowlands.
  double concavity = 0.3;      ///< θ of the slope–area law, in [0, 1]; 0 keeps s(p) everywhere.
  double referenceArea = 10.0; ///< km² at which an edge's slope is s(p); in (0, 10000].

  // --- Rosgen typing (Section 5.2) ---
  double straightMinSlope = 0.02;     ///< Sections at least this steep are B (straight), else E.
  double braidedMinFlow = 4.0;        ///< m³/s; D (braided) needs this flow ...
  double braidedMaxDistance = 3000.0; ///< ... within this river distance of its mouth.
  double deltaMinFlow = 6.0; ///< m³/s; a mouth with this flow is a D delta. Rosgen values ≥ 0.

  // --- Drainage below the river graph's scale (issue 25; experimental) ---
  /// Levels of procedural tributaries carved at evaluation time (400, 200, 100 m cells), in
  /// [0, 3]; 0 (the default) carves none. Not 0 also lets every river wander at two scales.
  /// Left out of the canonical JSON when 0, so worlds without it keep their cache keys.
  /// Costly: a tile takes about 13 times the CPU (docs/performance.md).
  int tributaryLevels = 0;

  // --- Erosion at generation (issue 36; docs/architecture.md, "Erosion at generation") ---
  // Experimental and opt-in: the erosion keys are left out of the canonical JSON while
  // erosionSteps is 0, so worlds without it keep their cache keys.
  double erosionCell = 60.0; ///< Lattice spacing of the erosion, m, in [30, 120].
  int erosionSteps = 0;      ///< Steps of the landscape evolution, in [0, 200]; 0: none; 20 tested.
  double erosionStrength = 1.0;      ///< Multiplier of the stream-power incision, in [0, 5].
  double hillslopeDiffusivity = 1.0; ///< Multiplier of the hillslope transport, in [0, 5].
  double erosionGrain = 1.0;         ///< Multiplier of the grain left after it, in [0, 5].

  // --- Vegetation layer (issue 28) ---
  /// The vegetation layer's response curves by species, replacing core/layers' defaults
  /// (layers::kSpecies) for the species named; empty: the defaults. JSON: "vegetation":
  /// {"tree": {"sediment": [r0, r1, f1, f0], "illumination": [...], "humidity": [...]}, ...}.
  /// Left out of the canonical JSON when empty, so worlds without it keep their cache keys.
  std::map<std::string, SpeciesCurves> vegetation;

  // --- Network grower (issue 30) ---
  /// The grower of the river network; JSON "grower": "grammar" (default) or "dla". Left out
  /// of the canonical JSON when "grammar", so worlds without it keep their cache keys.
  NetworkGrower grower = NetworkGrower::kGrammar;

  std::uint64_t seed = 1; ///< Seed of every random choice; JSON: an integer, or a decimal string.

  std::vector<ConstraintSource> constraints; ///< Constraint images, ≤ kMaxConstraints.

  /// Exact, field-by-field comparison.
  bool operator==(const Params&) const = default;
};

/// Parses params JSON (an object whose keys are the field names above, camelCase) on top
/// of the defaults, then validates it. Errors name the key: unknown keys (kInvalidInput,
/// suggesting the closest known key when ≤ 2 edits away), wrong types (kInvalidInput), values
/// outside their range (kOutOfRange), broken cross-field rules such as Pc + Pa + Ps ≠ 1 or
/// σ ≤ e/√2 (kInvalidInput), more than kMaxConstraints constraints (kLimitExceeded).
/// `limits` caps the size and nesting of the text.
base::Result<Params> parseParams(std::string_view json, const InputLimits& limits = {});

/// Checks the ranges and cross-field rules of `params` (what parseParams enforces).
base::Status validateParams(const Params& params);

/// Canonical JSON of every field (fixed key order, shortest round-trip numbers), for hashing;
/// parseParams(canonicalJson(p)) == p for every valid p (a -0.0 reads back as 0.0).
std::string canonicalJson(const Params& params);

} // namespace strahler::input
