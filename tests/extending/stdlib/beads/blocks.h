// The blocks of the test kit `beads` (tests/extending/stdlib/beads.ksm), written by following
// docs/extending.md: one C++ declaration per `extern` signature, in signature order; per-
// binding blocks (extractors, functions, term priors) take `const Scene&` first; factories
// (global priors, the likelihood, proposal sources) return the kit's parameter values.
#pragma once

#include <cmath>
#include <cstdint>
#include <variant>
#include <vector>

#include "runtime/domain/binding.h"

namespace ksmc::stdlib::beads::blocks {

struct Vec2 {
  double x = 0.0, y = 0.0;
};

// The model state generated code reads: `bead[i]` of the domain is s.vec2(i).
class Scene {
 public:
  explicit Scene(const std::vector<Vec2>& beads) : beads_(&beads) {}
  const Vec2& vec2(std::int32_t i) const { return (*beads_)[static_cast<std::size_t>(i)]; }
  const std::vector<Vec2>& vec2s() const { return *beads_; }

 private:
  const std::vector<Vec2>* beads_;
};

// The moves of `makes spawn / remove` and `makes nudge`.
enum class Move { spawn, remove, nudge };

namespace bead {
inline bool near(const Scene&, const Vec2& a, const Vec2& b, double dist) { return std::hypot(a.x - b.x, a.y - b.y) <= dist; }
inline bool far_out(const Scene&, const Vec2& a, double limit) { return std::hypot(a.x, a.y) > limit; }
}  // namespace bead

inline double gap(const Scene&, const Vec2& a, const Vec2& b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline double gaussian(const Scene&, double x, double sigma) { return -0.5 * (x / sigma) * (x / sigma); }

struct Count {
  double per_bead = 1.0;
};
using Prior = std::variant<Count>;
namespace bead {
inline Prior count(double per_bead) { return Count{per_bead}; }
}  // namespace bead

struct Nearest {
  double sigma = 0.5;
  double background = 0.05;
};
using Likelihood = std::variant<Nearest>;

struct Spawn {
  double spread = 0.2;
};
struct Nudge {
  double sigma = 0.1;
};
using Source = std::variant<Spawn, Nudge>;

namespace data {
inline Likelihood nearest(double sigma, double background) { return Nearest{sigma, background}; }
inline Source spawn(double spread) { return Spawn{spread}; }
}  // namespace data
namespace bead {
inline Source nudge(double sigma) { return Nudge{sigma}; }
}  // namespace bead

struct Output {};

using Binding = runtime::domain::Binding<Scene, Prior, Likelihood, Move, Source, Output>;

}  // namespace ksmc::stdlib::beads::blocks
