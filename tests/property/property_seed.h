// Seeds for the property-based tests (tests/property): deterministic by default, replayable.
//
// Every property runs first over the regression seeds its file keeps (every seed that ever failed),
// then over `iterations` seeds base, base + 1, ... The base is VOXREF_PROPERTY_SEED when that
// environment variable is set (decimal or 0x hex), else a fixed default, so CI is reproducible. A
// failure is reported under "seed=<n>"; VOXREF_PROPERTY_SEED=<n> makes <n> the first seed tried.
// The loop stops at the first failing seed so that one bug does not flood the log.
//
// Random numbers come from std::mt19937_64 (its output is fixed by the standard) through the
// helpers below, not through std::uniform_*_distribution, whose results differ between
// standard libraries.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace voxref::property {

inline constexpr std::uint64_t kDefaultBaseSeed = 0x766f78726566ull;  // "voxref"

inline std::uint64_t baseSeed() {
  const char* env = std::getenv("VOXREF_PROPERTY_SEED");
  return env && *env ? std::strtoull(env, nullptr, 0) : kDefaultBaseSeed;
}

using Rng = std::mt19937_64;

// Uniform in [lo, hi] (inclusive); the modulo bias is below 2^-32 for the ranges used here.
inline std::int64_t uniformInt(Rng& rng, std::int64_t lo, std::int64_t hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1u;
  return lo + static_cast<std::int64_t>(span == 0 ? rng() : rng() % span);
}
// Uniform in [0, 1) with 53 random bits.
inline double uniformUnit(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }
inline bool coin(Rng& rng, int percent) { return uniformInt(rng, 0, 99) < percent; }

// Runs body(rng) for every regression seed, then for `iterations` seeds from baseSeed().
template <class Body>
void forEachSeed(int iterations, std::initializer_list<std::uint64_t> regressionSeeds, Body&& body) {
  auto run = [&](std::uint64_t seed) {
    SCOPED_TRACE("seed=" + std::to_string(seed) + " (replay: VOXREF_PROPERTY_SEED=" + std::to_string(seed) + ")");
    Rng rng(seed);
    body(rng);
    return !::testing::Test::HasFailure();
  };
  for (const std::uint64_t seed : regressionSeeds)
    if (!run(seed)) return;
  const std::uint64_t base = baseSeed();
  for (int i = 0; i < iterations; ++i)
    if (!run(base + static_cast<std::uint64_t>(i))) return;
}

}  // namespace voxref::property
