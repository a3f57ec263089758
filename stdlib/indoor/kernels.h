// The nine sub-kernels of seed §3.5 as five reversible pairs: ADD/REMOVE, SPLIT/MERGE,
// SHRINK/DILATE, ALLOCATE/DELETE and INTERCHANGE (its own reverse). A proposal is a Move (a
// delta the caller applies to its ScoredWorld and reverts on rejection) with
//   log_q_fwd = log Q(W'|W), the probability of the choices this kernel made, and
//   log_q_bwd = log Q(W|W'), the reverse kernel's probability of proposing the inverse move on
//               W', computed with the reverse kernel's own weighting (§3.5.3).
// The engine adds log Phi(reverse) - log Phi(kernel) from its schedule. Kernels are
// engine-agnostic and const (safe to share between chains).
//
// Bottom-up sources are injected as function objects, so any detector plugs in:
//   unit candidates (ADD; WBU/FSU/RPB), split lines inside a unit (SPLIT), door candidates
//   (ALLOCATE). Their element types mirror ksmc::stdlib::indoor::detect's UnitCandidate,
//   SplitLine and DoorCandidate (use the to_candidates helpers to convert).
//
// Units or doors attached: a unit that carries a door is not changed by REMOVE or INTERCHANGE
// (the proposal is declined; DELETE its doors first); SHRINK/DILATE change it only when each of
// its doors stays on a wall of the changed rectangle (within door_snap). SPLIT and MERGE carry the
// doors of the units they remove to the units they add (each door to the one added unit with a
// wall under it; declined when that is not unique or the reverse would not carry it back).
// With seam doors (KernelSources::seam_doors) SPLIT also allocates door candidates on its cut
// and MERGE deletes the doors joining its two units.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "stdlib/indoor/map_evidence.h"
#include "stdlib/indoor/orientation_bias.h"
#include "stdlib/indoor/sampling.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

struct CandidateUnit {
  OrientedRect rect;
  double weight = 0.0;  // omega_r (eq. 3.10)
};
struct CandidateLine {
  Point2 a, b;
  double weight = 0.0;  // omega_e (eq. 3.18); <= 0 means: use the segment length
};
struct CandidateDoor {
  Point2 a, b;
  double weight = 0.0;  // omega_g (eq. 3.23)
};

// Converts any detector output with the same fields (e.g. detect::UnitCandidate).
template <class T>
std::vector<CandidateUnit> to_unit_candidates(const std::vector<T>& v) {
  std::vector<CandidateUnit> out;
  out.reserve(v.size());
  for (const auto& c : v) out.push_back({c.rect, c.weight});
  return out;
}
template <class T>
std::vector<CandidateLine> to_line_candidates(const std::vector<T>& v) {
  std::vector<CandidateLine> out;
  out.reserve(v.size());
  for (const auto& c : v) out.push_back({c.a, c.b, c.weight});
  return out;
}
template <class T>
std::vector<CandidateDoor> to_door_candidates(const std::vector<T>& v) {
  std::vector<CandidateDoor> out;
  out.reserve(v.size());
  for (const auto& c : v) out.push_back({c.a, c.b, c.weight});
  return out;
}

struct KernelSources {
  // Unit candidates for ADD given the current world (a detector may depend on it, e.g. FSU).
  std::function<std::span<const CandidateUnit>(const World&)> units;
  // Split lines detected inside `unit` (SPLIT).
  std::function<std::vector<CandidateLine>(const World&, const Unit& unit)> split_lines;
  // Door candidates for ALLOCATE given the current world.
  std::function<std::span<const CandidateDoor>(const World&)> doors;
  // Door candidates on the shared wall of two rectangles (SPLIT allocates them on its cut,
  // MERGE deletes the doors joining its two units); unset: neither does.
  std::function<std::vector<CandidateDoor>(const OrientedRect& a, const OrientedRect& b)> seam_doors;
};

struct KernelParams {
  double h_b = 20.0;                 // cap of the unit weight b_r (eq. 3.21)
  double h_v = 20.0;                 // cap of the wall weight v_w (eq. 3.22)
  double h_g = 20.0;                 // cap of the door weight z_g (eq. 3.28)
  double shift_sigma = 2.0;          // SHRINK/DILATE Gaussian wall shift, cells
  double interchange_sigma = 3.0;    // INTERCHANGE shared-wall shift, cells
  double min_size = 3.0;             // smallest side of a unit a kernel may create, cells
  double door_snap = 2.0;            // door segment to wall distance to attach, cells
  double door_angle = 10.0 * 3.14159265358979323846 / 180.0;  // door/wall angle tolerance
  double align_angle = 1e-6;         // units this close (mod 90 deg) share a frame, radians
  double coincide = 1e-6;            // coordinates this close coincide, cells
  // ADD draws this share of its proposals uniformly over rectangles (move.uniform_rect): centre
  // in the map, sides in [min_size, map diagonal] cells, orientation in [0, 90 deg). 0: the
  // detectors' candidates only, so REMOVE cannot undo a unit no detector proposes.
  double uniform_share = 0.0;
  OrientationBias orientation;       // dominant-orientation bias of ADD and SPLIT
};

struct Proposal {
  Move move;
  double log_q_fwd = 0.0;
  double log_q_bwd = 0.0;
};

class KernelSet {
 public:
  KernelSet(const MapEvidence& evidence, KernelSources sources, KernelParams params = {});

  // A move of kind `k` on `w`, or nullopt when the kernel cannot apply (declined).
  std::optional<Proposal> propose(KernelKind k, const World& w, Rng& rng) const;
  // log of the probability that kernel `k` proposes exactly `m` on `w` (-inf if it cannot).
  double log_q(KernelKind k, const World& w, const Move& m) const;

  const KernelParams& params() const { return params_; }
  const MapEvidence& evidence() const { return evidence_; }
  const KernelSources& sources() const { return sources_; }

 private:
  const MapEvidence& evidence_;
  KernelSources sources_;
  KernelParams params_;
};

}  // namespace ksmc::stdlib::indoor
