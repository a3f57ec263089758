// The semantic half of the indoor model (seed §3.8): the evidence extractors of the .ksm
// (RoLi/CoLi/HaLi: Table 3.6 size / aspect-ratio classifier; Adj: walls within the dilation;
// MulDoor: door count), Markov logic inference over the generated indoor factors
// (mln::infer, Method::Auto) with a small LRU cache keyed by the exact evidence, and the
// wall-length geometry of the semantic prior (wall_length_diff).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mln/evidence_cache.h"
#include "stdlib/indoor/kit/settings.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

enum class GeomClass : std::uint8_t { RoomLike, CorridorLike, HallLike };

// Table 3.6: hall-like when the longer side exceeds big_size; otherwise corridor-like when
// longer / shorter exceeds big_ratio, else room-like. `resolution` in m per cell.
GeomClass classify_unit(const OrientedRect& r, double resolution, const ClassifierSettings& c);

// The connecting walls of two units: the pair of nearly parallel edges (within 10 degrees)
// closest across and overlapping along, both within 2 * dilate + 1 cells. nullopt when none.
struct WallPair {
  int wall_a = 0, wall_b = 0;
  double overlap = 0.0;   // cells along the walls
  double length_a = 0.0, length_b = 0.0;  // cells
};
std::optional<WallPair> connecting_walls(const OrientedRect& a, const OrientedRect& b, double dilate_cells);

// wall_length_diff(a, b) in metres: |len_a - len_b| of the connecting walls; nullopt if none.
std::optional<double> wall_length_diff(const OrientedRect& a, const OrientedRect& b, double dilate_cells,
                                       double resolution);

inline constexpr int kTypes = 4;  // in SemanticSettings::type_predicates order

struct UnitSemantics {
  UnitId id = 0;
  std::array<double, kTypes> type_probs{};
  int type = 0;  // argmax (ties: lowest index)
};

struct SemanticResult {
  std::vector<UnitSemantics> units;                   // world order
  std::vector<std::pair<UnitId, UnitId>> adjacent;    // a < b
  std::vector<std::pair<UnitId, UnitId>> same_length; // a < b with P(SaLe(a,b)) passing the prior's test
  std::string method;                                 // of the MLN engine run
};

struct SemanticStats {
  std::uint64_t calls = 0, cache_hits = 0, inferences = 0;
  double inference_seconds = 0.0;
};

class SemanticEngine {
 public:
  // Throws ConfigError when the binding lacks a program or a predicate the settings name.
  SemanticEngine(const SemanticSettings& settings, const runtime::domain::MlnBinding& binding, double resolution,
                 std::uint64_t seed, std::size_t cache_size = 32);

  // Extracts the evidence of `world`, runs (or recalls) inference, returns the semantics.
  SemanticResult evaluate(const World& world);
  const SemanticStats& stats() const { return stats_; }
  const SemanticSettings& settings() const { return settings_; }

 private:
  struct Indexed {  // result in unit-index space, independent of unit ids
    std::vector<std::array<double, kTypes>> probs;
    std::vector<std::pair<int, int>> same_length;
    std::string method;
  };
  std::shared_ptr<const Indexed> infer(const std::vector<std::int32_t>& key, int n,
                                       const std::vector<std::pair<int, int>>& adj);

  SemanticSettings settings_;
  runtime::domain::MlnBinding binding_;
  double resolution_;
  std::uint64_t seed_;
  std::int32_t unit_type_ = 0;
  std::int32_t p_roli_ = 0, p_coli_ = 0, p_hali_ = 0, p_muldoor_ = 0, p_adj_ = 0, p_sale_ = 0;
  std::array<std::int32_t, kTypes> p_type_{};
  runtime::mln::EvidenceCache<Indexed, std::int32_t> cache_;
  SemanticStats stats_;
};

}  // namespace ksmc::stdlib::indoor::kit
