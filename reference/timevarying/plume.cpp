#include "reference/timevarying/plume.h"

#include "reference/common/fields.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace voxref::ref {
namespace {

struct Puff {
  double x, y, z, sigma, settling;
};

// The plume's concentration field, step by step (the puffs' transport, spreading and settling;
// what lands stays on the seabed): `perStep` sees each step's n^3 concentrations, x fastest.
template <class PerStep>
void simulatePlume(const PlumeOptions& o, PerStep&& perStep) {
  if (o.side < 8 || (o.side & (o.side - 1)) != 0) throw std::invalid_argument("plume side must be a power of two >= 8");
  const int n = o.side;
  const double scale = n / 128.0;  // the plume is designed on a 128^3 box and scales with it
  std::vector<Puff> puffs;
  std::vector<double> deposit(static_cast<std::size_t>(n) * n, 0.0);
  for (int t = 0; t < o.steps; ++t) {
    puffs.push_back({16.0 * scale, 64.0 * scale, 108.0 * scale, 1.6 * scale, (t % 2 ? 1.1 : 4.3) * scale});
    std::vector<double> c(static_cast<std::size_t>(n) * n * n, 0.0);
    std::vector<Puff> airborne;
    for (Puff p : puffs) {
      p.x += 2.6 * scale * (0.25 + p.z / n);  // current along +x, weaker near the seabed
      p.y += 0.35 * scale;                    // a slight cross drift
      p.z -= p.settling;
      p.sigma = std::sqrt(p.sigma * p.sigma + 0.35 * scale * scale);
      const double mass = 1.0 / (p.sigma * p.sigma * p.sigma);
      const int r = static_cast<int>(std::ceil(3.0 * p.sigma));
      const bool landed = p.z <= 0.0;
      for (int z = std::max(0, static_cast<int>(p.z) - r); z <= std::min(n - 1, static_cast<int>(p.z) + r); ++z)
        for (int y = std::max(0, static_cast<int>(p.y) - r); y <= std::min(n - 1, static_cast<int>(p.y) + r); ++y)
          for (int x = std::max(0, static_cast<int>(p.x) - r); x <= std::min(n - 1, static_cast<int>(p.x) + r); ++x) {
            const double dx = x + 0.5 - p.x, dy = y + 0.5 - p.y, dz = landed ? 0.0 : z + 0.5 - p.z;
            const double g = mass * std::exp(-(dx * dx + dy * dy + dz * dz) / (2.0 * p.sigma * p.sigma));
            if (landed) {
              if (z == 0) deposit[static_cast<std::size_t>(x) + static_cast<std::size_t>(n) * y] += 4.0 * g;
            } else {
              c[static_cast<std::size_t>(x) + static_cast<std::size_t>(n) * (y + static_cast<std::size_t>(n) * z)] += g;
            }
          }
      if (!landed && p.x < n + 3.0 * p.sigma) airborne.push_back(p);
    }
    puffs = std::move(airborne);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        c[static_cast<std::size_t>(x) + static_cast<std::size_t>(n) * y] +=
            deposit[static_cast<std::size_t>(x) + static_cast<std::size_t>(n) * y];
    perStep(c);
  }
}

// The voxel of a concentration under a gain.
std::uint8_t plumeVoxel(double gain, double c) {
  return static_cast<std::uint8_t>(std::min(255.0, std::floor(gain * c)));
}

}  // namespace

TimeSeries dischargePlume(const PlumeOptions& o) {
  TimeSeries s;
  s.side = o.side;
  s.original = {o.side, o.side, o.side};
  simulatePlume(o, [&](const std::vector<double>& c) {
    std::vector<std::uint8_t> vol(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) vol[i] = plumeVoxel(o.gain, c[i]);
    s.steps.push_back(std::move(vol));
  });
  return s;
}

TimeSeries driftingBlobs(int side, int steps) {
  if (side < 4 || (side & (side - 1)) != 0) throw std::invalid_argument("series side must be a power of two >= 4");
  const Field blobs = analyticField("gaussian_blobs");
  TimeSeries s;
  s.side = side;
  s.original = {side, side, side};
  for (int t = 0; t < steps; ++t) {
    std::vector<std::uint8_t> v(static_cast<std::size_t>(side) * side * side);
    std::size_t i = 0;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x, ++i) {
          const double value = blobs((x + 0.5 - t) / side, (y + 0.5) / side, (z + 0.5) / side);
          v[i] = static_cast<std::uint8_t>(std::min(255.0, 32.0 * std::floor(value * 8.0)));
        }
    s.steps.push_back(std::move(v));
  }
  return s;
}

double sparseness(const TimeSeries& s) {
  double zero = 0.0, total = 0.0;
  for (const auto& v : s.steps) {
    zero += static_cast<double>(std::count(v.begin(), v.end(), std::uint8_t{0}));
    total += static_cast<double>(v.size());
  }
  return total > 0.0 ? zero / total : 1.0;
}

TimeSeries dischargePlumeWithSparseness(PlumeOptions o, double target, double* achieved) {
  // Sparseness falls as the gain grows: bisect on log(gain) over [2^-4, 2^20]. A voxel is zero
  // under a gain exactly when plumeVoxel(gain, c) is, so the sparseness of every gain tried comes
  // from the concentrations alone: the field is simulated once, keeping only its positive values
  // (the plume is sparse), instead of once per gain; the bits are those of the full generation.
  std::vector<double> positive;
  double total = 0.0;
  simulatePlume(o, [&](const std::vector<double>& c) {
    total += static_cast<double>(c.size());
    for (double v : c)
      if (v > 0.0) positive.push_back(v);
  });
  const double alwaysZero = total - static_cast<double>(positive.size());
  auto sparsenessAt = [&](double gain) {
    std::size_t zero = 0;
    for (double v : positive) zero += plumeVoxel(gain, v) == 0;
    return total > 0.0 ? (alwaysZero + static_cast<double>(zero)) / total : 1.0;
  };
  double lo = -4.0, hi = 20.0;
  for (int i = 0; i < 26; ++i) {  // 24 / 2^26 in log2(gain): far below one voxel of difference
    const double mid = 0.5 * (lo + hi);
    (sparsenessAt(std::exp2(mid)) > target ? lo : hi) = mid;
  }
  o.gain = std::exp2(hi);
  TimeSeries s = dischargePlume(o);
  if (achieved) *achieved = sparseness(s);
  return s;
}

}  // namespace voxref::ref
