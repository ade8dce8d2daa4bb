// The synthetic corpus' random numbers: splitmix64 with its own uniform and integer maps, so a
// seed gives the same models with any compiler and standard library (std distributions are
// implementation-defined).
#pragma once

#include <cstdint>
#include <vector>

namespace opgraph {
namespace synth {

class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}

  uint64_t Next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // In [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(Next() >> 11) * 0x1.0p-53; }
  // In [lo, hi], inclusive.
  int Int(int lo, int hi) { return lo + static_cast<int>(Next() % static_cast<uint64_t>(hi - lo + 1)); }
  bool Chance(double p) { return Uniform(0, 1) < p; }
  double Sign() { return Chance(0.5) ? 1.0 : -1.0; }
  // A magnitude in [lo, hi] with a random sign.
  double SignedUniform(double lo, double hi) { return Sign() * Uniform(lo, hi); }
  // An index drawn with the given (non-negative, not all zero) weights.
  int Weighted(const std::vector<double>& weights) {
    double total = 0;
    for (double w : weights) total += w;
    double r = Uniform(0, total);
    for (size_t i = 0; i < weights.size(); ++i) {
      if (r < weights[i]) return static_cast<int>(i);
      r -= weights[i];
    }
    return static_cast<int>(weights.size()) - 1;
  }

 private:
  uint64_t state_;
};

// The seed of model `index` of the set with seed `set_seed`: each model is independent, so any
// subset (a test's sample, one parallel worker's share) is generated alone.
inline uint64_t ModelSeed(uint64_t set_seed, int index) {
  Random mix(set_seed * 0x100000001b3ULL + static_cast<uint64_t>(index));
  mix.Next();
  return mix.Next();
}

}  // namespace synth
}  // namespace opgraph
