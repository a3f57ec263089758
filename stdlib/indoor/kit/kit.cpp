#include "stdlib/indoor/kit/kit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "runtime/cli/work_estimate.h"
#include "runtime/domain/kernels.h"
#include "runtime/io/cancel.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/rpb.h"
#include "stdlib/indoor/detect/wbu.h"
#include "stdlib/indoor/io/map_cleanup.h"
#include "stdlib/indoor/io/map_frame.h"
#include "stdlib/indoor/io/map_loader.h"
#include "stdlib/indoor/io/posterior_plot.h"
#include "stdlib/indoor/io/route.h"
#include "stdlib/indoor/io/world_writer.h"
#include "stdlib/indoor/free_distance.h"
#include "stdlib/indoor/kit/after_run.h"
#include "stdlib/indoor/kit/indoor_model.h"
#include "stdlib/indoor/blocks/walls.h"

namespace ksmc::stdlib::indoor::kit {

namespace cli = runtime::cli;
namespace dom = runtime::domain;
namespace mcmc = runtime::mcmc;

namespace {

constexpr double kPiD = 3.14159265358979323846;

// "x,y" in metres (map frame) -> cell coordinates; `flag` names the flag in errors.
Point2 parse_point(const std::string& text, const io::OccupancyMap& map, const std::string& flag) {
  const auto comma = text.find(',');
  double x = 0.0, y = 0.0;
  bool ok = comma != std::string::npos;
  if (ok) {
    try {
      std::size_t n1 = 0, n2 = 0;
      x = std::stod(text.substr(0, comma), &n1);
      y = std::stod(text.substr(comma + 1), &n2);
      ok = n1 == comma && n2 == text.size() - comma - 1 && std::isfinite(x) && std::isfinite(y);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok) throw cli::UsageError("--" + flag + ": expected x,y in metres (map frame), got '" + text + "'");
  const Point2 p = io::frame_of(map).to_cells({x, y});  // map_server frame (io/map_frame.h)
  if (!(p.x >= -0.5 && p.y >= -0.5 && p.x < map.cols() - 0.5 && p.y < map.rows() - 0.5))
    throw cli::UsageError("--" + flag + " " + text + ": outside the map");
  return p;
}

Point2 parse_robot(const std::string& text, const io::OccupancyMap& map) { return parse_point(text, map, "robot"); }

// --path "X1,Y1 X2,Y2": start and goal in cells.
std::pair<Point2, Point2> parse_path(const std::string& text, const io::OccupancyMap& map) {
  const auto space = text.find(' ');
  if (space == std::string::npos) throw cli::UsageError("--path: expected two points X1,Y1 X2,Y2 in metres, got '" + text + "'");
  return {parse_point(text.substr(0, space), map, "path"), parse_point(text.substr(space + 1), map, "path")};
}

std::uint64_t flag_count(const cli::FlagValues& f, const std::string& name) {
  const long long v = f.integer(name);
  if (v < 0) throw cli::UsageError("--" + name + " must be >= 0");
  return static_cast<std::uint64_t>(v);
}

io::WorldResult make_result(IndoorModel& m, const io::OccupancyMap& map, const std::string& source,
                            const mcmc::RunResult& run) {
  io::WorldResult r;
  r.map = io::map_info_of(map, source);
  r.wall_thickness = m.scored().params().raster.wall_thickness;
  const World& w = m.scored().world();
  const auto sem = m.final_semantics();
  if (sem) {
    r.types = m.semantics()->type_names();
    r.queries = m.semantics()->queries_json(*sem);
    // Conditional prior bindings (e.g. SaLe pairs) and those more than 2 sd off (violations).
    r.metrics["conditional_bindings"] = static_cast<double>(sem->terms.size());
    r.metrics["conditional_beyond_2sd"] = static_cast<double>(sem->strained);
  }
  for (std::size_t i = 0; i < w.units().size(); ++i) {
    const Unit& u = w.units()[i];
    io::UnitResult ur;
    ur.id = static_cast<int>(u.id);
    ur.corners = u.rect.corners();
    if (sem && sem->type[i] >= 0) {
      ur.type = r.types[static_cast<std::size_t>(sem->type[i])];
      for (std::size_t k = 0; k < r.types.size(); ++k) ur.type_probs[r.types[k]] = sem->type_probs[i][k];
    }
    r.units.push_back(std::move(ur));
  }
  for (const Door& d : w.doors())
    r.doors.push_back({static_cast<int>(d.id), static_cast<int>(d.unit_a), static_cast<int>(d.unit_b), {d.a, d.b}});
  const auto units = w.units();
  for (std::size_t i = 0; i < units.size(); ++i)
    for (std::size_t j = i + 1; j < units.size(); ++j)
      if (blocks::connecting_walls(units[i].rect, units[j].rect, blocks::kDefaultDilateCells))
        r.adjacent.emplace_back(static_cast<int>(units[i].id), static_cast<int>(units[j].id));
  const double secs = run.seconds;
  r.metrics["cell_prediction_rate"] = m.scored().cell_prediction_rate();
  // Where K's misses are: cells by observed class and predicted class (the diagonal is K's
  // numerator), e.g. cells_occupied_predicted_free = furniture and clutter inside units.
  const CellConfusion confusion = cell_confusion(m.scored().histogram());
  const char* observed[] = {"free", "unknown", "occupied"};
  const char* predicted[] = {"free", "unknown", "wall"};
  for (std::size_t o = 0; o < 3; ++o)
    for (std::size_t p = 0; p < 3; ++p)
      r.metrics[std::string("cells_") + observed[o] + "_predicted_" + predicted[p]] = static_cast<double>(confusion[o][p]);
  r.metrics["iterations"] = static_cast<double>(run.iterations);
  r.metrics["seconds"] = secs;
  r.metrics["iterations_per_second"] = secs > 0.0 ? static_cast<double>(run.iterations) / secs : 0.0;
  r.metrics["log_posterior"] = m.log_posterior();
  r.metrics["log_likelihood"] = m.log_likelihood();
  r.metrics["log_prior"] = m.log_prior();
  r.metrics["log_knowledge"] = m.log_knowledge();
  r.metrics["units"] = static_cast<double>(w.units().size());
  r.metrics["doors"] = static_cast<double>(w.doors().size());
  r.metrics["best_iteration"] = static_cast<double>(run.best().best_iteration);
  // Only a recorded trace (--trace / --trace-every); without one there is no trace.png.
  for (const auto& t : run.best().trace) r.trace.push_back({static_cast<std::int64_t>(t.iteration), t.log_posterior, t.acceptance_window});
  return r;
}

// The unit rectangles of the last stored posterior samples of the best chain (--samples), for
// posterior.png: each sample is restored into `m` (the model's own reading of its snapshot), then
// `m` goes back to the best state.
std::vector<io::PosteriorWorld> posterior_worlds(IndoorModel& m, const mcmc::RunResult& run) {
  std::vector<io::PosteriorWorld> out;
  const auto& samples = run.best().samples;
  if (samples.empty()) return out;
  const std::size_t first = samples.size() > io::kPosteriorMaxDrawn ? samples.size() - io::kPosteriorMaxDrawn : 0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    m.restore(samples[i].state);
    auto& pw = out.emplace_back();
    pw.iteration = static_cast<std::int64_t>(samples[i].iteration);
    for (const Unit& u : m.scored().world().units()) pw.units.push_back(u.rect.corners());
  }
  m.restore(run.best().best_state);
  return out;
}

// Fixed unit candidates of each pool (WBU, and RPB with --robot) and the FSU frame.
struct FixedSources {
  std::vector<std::vector<CandidateUnit>> units;
  double frame_deg = 0.0;
  std::size_t wbu_count = 0;
  bool rpb_found = false;
};

FixedSources fixed_sources(const KitPlan& plan, const io::OccupancyMap& map, const cli::DomainInput& in) {
  FixedSources out;
  const double res = map.resolution;
  std::map<std::pair<double, int>, std::vector<CandidateUnit>> wbu_runs;  // by (min_size, max_units)
  bool framed = false;
  for (const auto& pool : plan.pools)
    for (const auto& w : pool.wbu) {
      const auto key = std::make_pair(w.min_size, w.max_units);
      if (wbu_runs.count(key)) continue;
      detect::WbuParams wp;
      wp.min_side = w.min_size / res;
      wp.max_candidates = static_cast<std::size_t>(w.max_units);
      const auto wbu = detect::detect_wbu_units(map.grid, wp);
      wbu_runs[key] = to_unit_candidates(wbu.candidates);
      if (!framed) {
        out.wbu_count = wbu.candidates.size();
        if (!wbu.frames_deg.empty()) out.frame_deg = wbu.frames_deg.front();
        framed = true;
      }
    }
  if (!framed) out.frame_deg = detect::dominant_orientation(map.grid).angle_deg;
  const bool robot = in.flags.given("robot");
  bool any_rpb = false;
  for (const auto& pool : plan.pools) {
    auto& units = out.units.emplace_back();
    for (const auto& w : pool.wbu) {
      const auto& c = wbu_runs.at({w.min_size, w.max_units});
      units.insert(units.end(), c.begin(), c.end());
    }
    for (const auto& rpb : pool.rpb) {
      any_rpb = true;
      if (!robot) continue;
      detect::RpbParams rp;
      rp.frame_deg = out.frame_deg;
      rp.min_side = rpb.min_size / res;
      if (auto c = detect::detect_rpb_unit(map.grid, parse_robot(in.flags.text("robot"), map), rp)) {
        units.push_back({c->rect, c->weight});
        out.rpb_found = true;
      }
    }
  }
  if (robot && !any_rpb) throw cli::UsageError("--robot: the domain file declares no detect.rpb source");
  return out;
}

// The cost of a run on `map` (issue 16). Measured with `/usr/bin/time -v indoor MAP.pgm
// --iterations 500|2000` on maps tiled from examples/indoor/sim_office.pgm (1200 x 800 to
// 7200 x 4800 cells; docs/reliability.md, "Bounded work", lists the runs):
//  * peak RSS = 75 MB + 38 bytes per cell, the same for 1, 2 or 4 chains (the map is shared);
//  * time = 1 s + (5e-7 s x cells + 7e-14 s x cells^2 (model construction: 90 s at 34.6 M
//    cells, 6 s at 8.6 M) + iterations x (0.5 ms + 5e-11 s x cells)) x chain rounds.
// At 10000 x 10000 cells and the default 10,000 iterations that is 3.9 GB and ~14 min
// (issue 16 measured 3.5 GB and 12-22 min). Times were taken on 2 shared cores (load ~10):
// expect a factor of 2 either way.
cli::WorkEstimate map_estimate(const std::filesystem::path& path, const io::OccupancyMap& map, const cli::DomainInput& in) {
  constexpr double kBaseMb = 75.0, kBytesPerCell = 38.0;
  constexpr double kBaseSeconds = 1.0, kBuildPerCell = 5e-7, kBuildPerCellSquared = 7e-14;
  constexpr double kIterationSeconds = 5e-4, kIterationPerCell = 5e-11;
  const double cells = static_cast<double>(map.rows()) * map.cols();
  const double threads = in.threads != 0 ? in.threads : std::max(1U, std::thread::hardware_concurrency());
  const double chains = std::max(1U, in.chains);
  const double rounds = std::ceil(chains / std::min(threads, chains));
  const double per_chain = kBuildPerCell * cells + kBuildPerCellSquared * cells * cells +
                           static_cast<double>(in.iterations) * (kIterationSeconds + kIterationPerCell * cells);
  cli::WorkEstimate e;
  e.input = path.string();
  e.what = "a " + std::to_string(map.cols()) + " x " + std::to_string(map.rows()) + " map";
  e.memory_mb = kBaseMb + kBytesPerCell * cells / 1e6;
  e.seconds = kBaseSeconds + per_chain * rounds;
  return e;
}

cli::DomainSetup load(const std::shared_ptr<const blocks::Binding>& binding, const cli::DomainInput& in) {
  auto shared = std::make_shared<SharedInput>();
  shared->binding = binding;
  shared->plan = make_plan(*binding);
  const KitPlan& plan = shared->plan;
  const std::filesystem::path path = in.inputs.at(0);

  io::ImageLoadOptions opts;
  if (in.flags.given("resolution")) {
    const double r = in.flags.real("resolution");
    if (!(r > 0.0) || !std::isfinite(r)) throw cli::UsageError("--resolution must be a positive number of metres per cell");
    opts.resolution = r;
  }
  const std::string th = in.flags.text("thresholds");
  const auto thresholds = io::Thresholds::by_name(th);
  if (!thresholds) throw cli::UsageError("--thresholds must be 'drawn', 'strict', 'ros' or 'bormann', got '" + th + "'");
  opts.thresholds = *thresholds;
  auto map = std::make_shared<io::OccupancyMap>(io::load_map(path, opts));
  for (const auto& w : map->warnings) std::fprintf(stderr, "%s\n", w.c_str());  // also in summary.json
  runtime::io::throw_if_cancelled("indoor: after reading the map");  // large maps: each step takes long
  cli::check_work(map_estimate(path, *map, in), in);  // large maps: cost said up front, refused above --max-memory-mb
  if (map->counts().free == 0) throw std::runtime_error(path.string() + ": the map has no free cell");
  const double res = map->resolution;
  const double speck_size = in.flags.real("speck-size");
  if (!(speck_size >= 0.0) || !std::isfinite(speck_size)) throw cli::UsageError("--speck-size must be >= 0 metres");
  // At most the map's larger side: a huge --speck-size must not overflow the cell count.
  const int speck_cells = static_cast<int>(
      std::min(std::floor(speck_size / res + 1e-9), static_cast<double>(std::max(map->rows(), map->cols()))));
  const double solid_depth = in.flags.real("solid-depth");
  if (!(solid_depth >= 0.0) || !std::isfinite(solid_depth)) throw cli::UsageError("--solid-depth must be >= 0 metres");
  const io::MapCleanup cleanup{speck_cells, solid_depth / res};
  cli::stage(in, "clearing specks and classifying solid interiors");
  const io::CleanupCounts cleaned = io::apply_cleanup(map->grid, cleanup);
  runtime::io::throw_if_cancelled("indoor: after the solid interior");
  shared->grid = map->grid;
  shared->resolution = res;
  shared->seed = in.seed;
  shared->tuning.source_refresh = flag_count(in.flags, "source-refresh");

  cli::stage(in, "finding wall orientations and unit candidates");
  FixedSources fixed = fixed_sources(plan, *map, in);
  runtime::io::throw_if_cancelled("indoor: after the fixed sources");
  shared->fixed_units = std::move(fixed.units);
  shared->frame_deg = fixed.frame_deg;
  shared->score.tables = plan.tables;
  shared->score.prior = plan.prior;
  shared->kernel.min_size = std::max(3.0, 0.3 / res);
  shared->kernel.orientation.enabled = true;
  shared->kernel.orientation.dominant = fixed.frame_deg * kPiD / 180.0;
  cli::stage(in, "indexing the map evidence");
  shared->evidence = std::make_unique<MapEvidence>(map->grid, 1);
  shared->free_distance = free_distance(shared->grid);

  cli::DomainSetup setup;
  const blocks::KernelDecl* first = binding->kernels.data();  // KitPlan::kernels has the same order
  dom::KernelTable table = dom::make_kernels(binding->kernels, binding->schedule, [first](const blocks::KernelDecl& d) {
    return std::make_shared<IndoorKernel>(d.name, d.reverse, static_cast<std::size_t>(&d - first));
  });
  setup.kernels = std::move(table.kernels);
  setup.schedule = std::move(table.schedule);
  std::shared_ptr<const SharedInput> cshared = shared;
  setup.model_factory = [cshared](unsigned) { return std::make_unique<IndoorModel>(cshared); };
  // --iterations auto (the default) stops a chain once its best world explains less than one
  // more cell over the plateau window (docs/indoor_outputs.md, "How long a run is").
  // A domain whose tables do not reward some correct prediction has no such unit: strict.
  try {
    setup.plateau_gain = one_cell_gain(LikelihoodModel(plan.tables));
    char gain_text[32];
    std::snprintf(gain_text, sizeof gain_text, "%.4f", setup.plateau_gain);
    setup.plateau_gain_what = std::string("one cell: the smallest log-likelihood gain of correcting one cell's "
                                          "prediction under the domain's tables (") + gain_text + " nats)";
  } catch (const std::invalid_argument&) {
    setup.plateau_gain = 0.0;
    setup.plateau_gain_what = "strict: a likelihood table of the domain does not reward every correct prediction";
  }
  if (map->image != map->source) setup.extra_inputs.push_back(map->image);
  if (plan.semantic)
    setup.evidence_db = [](mcmc::Model& best) {
      auto& m = static_cast<IndoorModel&>(best);
      const auto sem = m.final_semantics();
      return m.semantics()->evidence_db(*sem);
    };
  const std::string source = path.filename().string();
  std::optional<std::pair<Point2, Point2>> route;  // --path start and goal, cells
  if (in.flags.given("path")) route = parse_path(in.flags.text("path"), *map);
  setup.write_results = [map, source, route, cleanup](const mcmc::RunResult& run, mcmc::Model& best, cli::OutputDir& out) {
    auto& m = static_cast<IndoorModel&>(best);
    auto posterior = posterior_worlds(m, run);  // restores the best state when done
    const auto search_start = std::chrono::steady_clock::now();
    const AfterRunResult after = improve_after_run(m);
    const double search_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - search_start).count();
    io::WorldResult result = make_result(m, *map, source, run);
    result.map.cleanup = cleanup;
    result.posterior = std::move(posterior);
    result.metrics["units_removed_after_run"] = static_cast<double>(after.removed.size());
    result.metrics["units_merged_after_run"] = static_cast<double>(after.merged.size());
    result.metrics["units_split_after_run"] = static_cast<double>(after.split.size());
    result.metrics["after_run_seconds"] = search_seconds;
    result.metrics["chain_best_log_posterior"] = after.log_posterior_before;
    nlohmann::ordered_json path_json;
    if (route) {
      std::string error;
      path_json = io::plan_route(result, route->first, route->second, error);
      if (!error.empty()) std::fprintf(stderr, "indoor: error: --path: %s (path.json says so)\n", error.c_str());
    }
    const io::WorldFiles files = io::write_world_outputs(out.dir(), *map, result);
    if (route) io::write_path_json(out.dir() / "path.json", path_json);
    if (!files.graph_png_skipped.empty()) std::fprintf(stderr, "indoor: %s\n", files.graph_png_skipped.c_str());
  };
  nlohmann::json extra = nlohmann::json::object();
  extra["map"] = {{"rows", map->rows()}, {"cols", map->cols()}, {"resolution", res},
                  {"free", map->counts().free}, {"occupied", map->counts().occupied}, {"unknown", map->counts().unknown}};
  extra["warnings"] = map->warnings;
  extra["wbu_candidates"] = fixed.wbu_count;
  extra["rpb_candidate"] = fixed.rpb_found;
  extra["frame_deg"] = fixed.frame_deg;
  extra["solid_interior"] = {{"depth_m", solid_depth}, {"cells_unexplained", cleaned.solid_unexplained}};
  extra["specks"] = {{"size_m", speck_size}, {"size_cells", speck_cells}, {"cells_cleared", cleaned.specks_cleared}};
  extra["semantic"] = {{"enabled", plan.semantic}, {"mln_prior", plan.mln_prior}};
  setup.summary_extra = std::move(extra);
  return setup;
}

}  // namespace

cli::DomainSpec domain_spec(const blocks::Binding& b) {
  auto binding = std::make_shared<const blocks::Binding>(b);
  cli::DomainSpec spec;
  spec.name = binding->domain;
  spec.version = "1.0";
  spec.description =
      "semantic indoor maps: typed space units and doors from an occupancy grid.\n"
      "Writes world.json, segmentation.png, labels.png, overlay.png, graph.dot/png, world.obj; trace.png with --trace,\n"
      "posterior.png with --samples N, path.json with --path (docs/indoor_outputs.md)";
  spec.inputs_help = "MAP.(png|pgm|yaml)";
  spec.default_iterations = 10000;
  spec.default_iterations_auto = true;
  using K = cli::DomainFlag::Kind;
  spec.flags = {
      {"resolution", "metres per cell (overrides the YAML / PGM comment; default 0.05 for bare images)", "", K::real},
      {"robot", "robot position x,y in metres (map frame): seeds the RPB detector", "", K::text},
      {"thresholds", "grey values of bare images (a YAML sets its own): drawn (>= 250 free, < 89 occupied, between: the one grey painting >= 5 % of the image unknown, the other greys occupied: drawn plans' grey walls and SLAM images' unexplored paint both read right), strict (>= 250 free, < 89 occupied, else unknown), ros (map_server) or bormann (>= 250 free, else occupied)", "drawn", K::text},
      {"source-refresh", "proposals between FSU / door candidate refreshes", "200", K::integer},
      {"path", "X1,Y1 X2,Y2: a route (metres, map frame) from the first point to the second over the door graph, written to path.json and drawn on overlay.png", "", K::text, false, 2},
      {"speck-size", "occupied specks in open floor (8-connected, every neighbour free) no wider than this (m) read as free: a SLAM map's noise, which would read as walls between units (0 = keep them)", "0.1", K::real},
      {"solid-depth", "occupied cells farther than this (m) from every free cell are classified unexplained: the inside of solid black regions, e.g. a map's outside painted black (0 = eq. 3.7 as is)", "0.5", K::real},
  };
  spec.load = [binding](const cli::DomainInput& in) { return load(binding, in); };
  return spec;
}

}  // namespace ksmc::stdlib::indoor::kit
