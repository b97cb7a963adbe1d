#include "strahler/landscape/evolution.h"

#include "strahler/base/random.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>
#include <vector>

namespace strahler::landscape {
namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;
/// Heights a filled depression rises by per metre of lattice, so that it drains.
constexpr double kFillGradient = 1e-3;
/// Largest share of (S/S_c)² the hillslope flux uses: its factor stays ≤ 1 / (1 − this).
constexpr double kSteepestShare = 0.75;
/// Largest explicit diffusion coefficient per edge of four: half the linear limit of 0.25, as
/// the nonlinear flux grows faster than its coefficient (at 0.24 steep slopes oscillated into
/// a checkerboard).
constexpr double kStableCoefficient = 0.12;
/// Drainage areas (in cells) whose A^m is tabled instead of computed.
constexpr std::size_t kTabled = 1 << 16;

struct Neighbour {
  int dc, dr;
};
/// The receivers' candidates: the four edge neighbours (a channel along a diagonal would be
/// dammed between its nodes once the lattice is interpolated).
constexpr std::array<Neighbour, 4> kNeighbours{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};

/// Uniform in [0, 1) from (seed, step, node).
double draw(std::uint64_t seed, int step, std::size_t node) noexcept {
  const std::uint64_t h =
      base::mixHash(base::mixHash(seed, static_cast<std::uint64_t>(step)), node);
  return static_cast<double>(h >> 11) * 0x1p-53;
}

class Solver {
public:
  Solver(const EvolutionInput& input, const EvolutionParams& params)
      : in_(input), p_(params), w_(input.tree.columns), h_(input.tree.rows), z_(input.tree),
        receiver_(input.tree.size(), kNone), order_(),
        area_(LatticeGrid<float>::filled(w_, h_, 0.0f)), scratch_(input.tree.size(), 0.0) {
    order_.reserve(z_.size());
    threads_ = p_.threads > 0
                   ? p_.threads
                   : static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    for (std::size_t i = 0; i < z_.size(); ++i) {
      if (!fixed(i)) {
        free_.push_back(static_cast<std::uint32_t>(i));
        continue;
      }
      const int c = static_cast<int>(i % static_cast<std::size_t>(w_));
      const int r = static_cast<int>(i / static_cast<std::size_t>(w_));
      bool shore = false; // only fixed nodes beside free ones can receive
      for (const Neighbour& n : kNeighbours) {
        const int cc = c + n.dc, rr = r + n.dr;
        shore = shore || (cc >= 0 && rr >= 0 && cc < w_ && rr < h_ && !fixed(z_.at(cc, rr)));
      }
      if (shore)
        outlets_.push_back(static_cast<std::uint32_t>(i));
    }
    // A^m for drainage areas of up to kTabled cells (areas are whole numbers of cells).
    const double cell = p_.spacing * p_.spacing;
    areaPower_.resize(kTabled + 1);
    for (std::size_t k = 0; k <= kTabled; ++k)
      areaPower_[k] = std::pow(static_cast<double>(k) * cell, p_.areaExponent);
  }

  EvolutionResult run(const base::ProgressCallback& progress) {
    fillDepressions(z_, in_.roles, kFillGradient * p_.spacing);
    for (int step = 0; step < p_.steps; ++step) {
      chooseReceivers(step);
      orderFromBaseLevels();
      accumulateArea();
      incise();
      diffuse();
      if (progress)
        progress("erosion", static_cast<double>(step + 1) / p_.steps);
    }
    fillDepressions(z_, in_.roles, kFillGradient * p_.spacing);
    return {std::move(z_), std::move(area_)};
  }

private:
  bool fixed(std::size_t i) const noexcept { return in_.roles.values[i] != NodeRole::kFree; }

  /// A receiver per free node: a lower neighbour drawn with probability ∝ slope^p, or the
  /// lowest neighbour of a pit.
  void chooseReceivers(int step) {
    forRows([&](int r) { chooseReceiversOfRow(step, r); });
  }

  void chooseReceiversOfRow(int step, int r) {
    const std::vector<double>& z = z_.values;
    for (int c = 0; c < w_; ++c) {
      const std::size_t i = z_.at(c, r);
      if (fixed(i)) {
        receiver_[i] = static_cast<std::uint32_t>(i);
        continue;
      }
      std::array<double, 4> weight{};
      std::array<std::uint32_t, 4> index{};
      double total = 0.0, lowest = z[i];
      std::uint32_t lowestIndex = kNone, pitIndex = kNone;
      double pitHeight = 0.0;
      int count = 0;
      for (const Neighbour& n : kNeighbours) {
        const int cc = c + n.dc, rr = r + n.dr;
        if (cc < 0 || rr < 0 || cc >= w_ || rr >= h_)
          continue;
        const std::size_t j = z_.at(cc, rr);
        const double drop = z[i] - z[j];
        if (pitIndex == kNone || z[j] < pitHeight) {
          pitIndex = static_cast<std::uint32_t>(j);
          pitHeight = z[j];
        }
        if (drop <= 0.0)
          continue;
        const double slope = drop; // per spacing: only the ratios matter
        const double wgt = p_.routingExponent == 1.0 ? slope : std::pow(slope, p_.routingExponent);
        weight[static_cast<std::size_t>(count)] = wgt;
        index[static_cast<std::size_t>(count)] = static_cast<std::uint32_t>(j);
        ++count;
        total += wgt;
        if (z[j] < lowest) {
          lowest = z[j];
          lowestIndex = static_cast<std::uint32_t>(j);
        }
      }
      if (count == 0) {
        receiver_[i] = pitIndex;
        continue;
      }
      double pick = draw(p_.seed, step, i) * total;
      std::uint32_t chosen = lowestIndex;
      for (int k = 0; k < count; ++k) {
        pick -= weight[static_cast<std::size_t>(k)];
        if (pick < 0.0) {
          chosen = index[static_cast<std::size_t>(k)];
          break;
        }
      }
      receiver_[i] = chosen;
    }
  }

  /// A^m for a drainage area of `area` m² (a whole number of cells).
  double areaPower(double area) const noexcept {
    const double cells = area / (p_.spacing * p_.spacing);
    if (cells < static_cast<double>(kTabled))
      return areaPower_[static_cast<std::size_t>(std::lround(cells))];
    return std::pow(area, p_.areaExponent);
  }

  /// order_: every node reachable from a fixed node against the receivers, receivers first:
  /// depth first from each fixed node in index order (Braun & Willett's stack), so that a
  /// catchment's nodes lie together in the order and in memory.
  void orderFromBaseLevels() {
    const std::size_t n = z_.size();
    donorStart_.assign(n + 1, 0);
    for (const std::uint32_t i : free_)
      if (receiver_[i] != kNone)
        ++donorStart_[receiver_[i] + 1];
    for (std::size_t i = 0; i < n; ++i)
      donorStart_[i + 1] += donorStart_[i];
    donors_.resize(donorStart_[n]);
    std::vector<std::uint32_t>& fill = fillAt_;
    fill.assign(donorStart_.begin(), donorStart_.end() - 1);
    for (const std::uint32_t i : free_)
      if (receiver_[i] != kNone)
        donors_[fill[receiver_[i]]++] = i;
    order_.clear();
    std::vector<std::uint32_t>& pending = fillAt_; // reused as the depth-first stack
    for (const std::uint32_t root : outlets_) {
      if (donorStart_[root + 1] == donorStart_[root])
        continue;
      pending.clear();
      pending.push_back(static_cast<std::uint32_t>(root));
      while (!pending.empty()) {
        const std::uint32_t i = pending.back();
        pending.pop_back();
        order_.push_back(i);
        for (std::uint32_t d = donorStart_[i + 1]; d-- > donorStart_[i];)
          pending.push_back(donors_[d]);
      }
    }
  }

  void accumulateArea() {
    const auto cell = static_cast<float>(p_.spacing * p_.spacing);
    std::fill(area_.values.begin(), area_.values.end(), 0.0f);
    for (std::size_t k = order_.size(); k-- > 0;) {
      const std::uint32_t i = order_[k];
      if (fixed(i))
        continue;
      area_.values[i] += cell;
      area_.values[receiver_[i]] += area_.values[i];
    }
  }

  /// Stream power and restoring uplift, implicit, receivers first.
  void incise() {
    std::vector<double>& z = z_.values;
    const std::vector<double>& tree = in_.tree.values;
    const double pull = p_.restoring;
    std::fill(scratch_.begin(), scratch_.end(), 0.0); // 1: solved this step
    for (const std::uint32_t i : order_) {
      scratch_[i] = 1.0;
      if (fixed(i))
        continue;
      const std::uint32_t r = receiver_[i];
      const double length = p_.spacing; // edge neighbours only
      const double base = z[r];
      if (z[i] <= base) { // a pit's receiver: only the uplift
        z[i] = (z[i] + pull * tree[i]) / (1.0 + pull);
        continue;
      }
      const auto area = static_cast<double>(area_.values[i]);
      if (area <= p_.channelArea) { // a hillslope: only the uplift (and creep, below)
        z[i] = std::max((z[i] + pull * tree[i]) / (1.0 + pull), base + kFillGradient * length);
        continue;
      }
      const double f = p_.incision * in_.erodibility.values[i] * (1.0 - p_.channelArea / area) *
                       areaPower(area) / length;
      const double next = (z[i] + pull * tree[i] + f * base) / (1.0 + pull + f);
      z[i] = std::max(next, base + kFillGradient * length);
    }
    for (const std::uint32_t i : free_) // cut off from every base level: uplift only
      if (scratch_[i] == 0.0)
        z[i] = (z[i] + pull * tree[i]) / (1.0 + pull);
  }

  /// Nonlinear hillslope transport over the four edges of each node, explicit. Each free node
  /// sums the fluxes of its own edges (the flux of an edge is the same number, of opposite
  /// sign, seen from either end), so rows are independent and the result does not depend on
  /// the threads.
  void diffuse() {
    const std::vector<double>& z = z_.values;
    std::vector<double>& change = scratch_;
    const double inverseCritical2 = 1.0 / (p_.criticalSlope * p_.criticalSlope);
    const double inverseSpacing2 = 1.0 / (p_.spacing * p_.spacing);
    const auto flux = [&](std::size_t from, std::size_t to) {
      const double difference = z[from] - z[to];
      const double share =
          std::min(difference * difference * inverseSpacing2 * inverseCritical2, kSteepestShare);
      const double coefficient = std::min(
          p_.diffusivity * 0.5 *
              static_cast<double>(in_.diffusivity.values[from] + in_.diffusivity.values[to]) /
              (1.0 - share),
          kStableCoefficient);
      return coefficient * difference;
    };
    forRows([&](int r) {
      for (int c = 0; c < w_; ++c) {
        const std::size_t i = z_.at(c, r);
        if (fixed(i)) {
          change[i] = 0.0;
          continue;
        }
        double sum = 0.0;
        if (c + 1 < w_)
          sum -= flux(i, i + 1);
        if (c > 0)
          sum -= flux(i, i - 1);
        if (r + 1 < h_)
          sum -= flux(i, z_.at(c, r + 1));
        if (r > 0)
          sum -= flux(i, z_.at(c, r - 1));
        change[i] = sum;
      }
    });
    std::vector<double>& heights = z_.values;
    for (std::size_t i = 0; i < heights.size(); ++i)
      heights[i] += change[i];
  }

  /// fn(r) for every row, rows spread over the threads (each row's work touches only its row's
  /// outputs, so the result does not depend on the threads).
  template <class Fn> void forRows(const Fn& fn) {
    const int threads = threads_;
    if (threads <= 1) {
      for (int r = 0; r < h_; ++r)
        fn(r);
      return;
    }
    std::vector<std::thread> pool;
    const auto work = [&](int first) {
      const int begin = h_ * first / threads, end = h_ * (first + 1) / threads;
      for (int r = begin; r < end; ++r)
        fn(r);
    };
    for (int t = 1; t < threads; ++t)
      pool.emplace_back(work, t);
    work(0);
    for (std::thread& t : pool)
      t.join();
  }

  const EvolutionInput& in_;
  int threads_ = 1;
  const EvolutionParams& p_;
  int w_, h_;
  LatticeGrid<double> z_;
  std::vector<std::uint32_t> receiver_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> free_;    // the free nodes, ascending
  std::vector<std::uint32_t> outlets_; // the fixed nodes beside free ones, ascending
  std::vector<double> areaPower_;      // (k cells)^m for k ≤ kTabled
  std::vector<std::uint32_t> donorStart_, donors_, fillAt_;
  LatticeGrid<float> area_;
  std::vector<double> scratch_;
};

} // namespace

EvolutionResult evolveLandscape(const EvolutionInput& input, const EvolutionParams& params,
                                const base::ProgressCallback& progress) {
  return Solver(input, params).run(progress);
}

} // namespace strahler::landscape
