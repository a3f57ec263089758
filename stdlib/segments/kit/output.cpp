#include "stdlib/segments/kit/output.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::segments::kit {

namespace {

// Rounds for stable, readable JSON (0.1 mm / 1e-6).
double r4(double v) { return std::round(v * 1e4) / 1e4; }
double r6(double v) { return std::round(v * 1e6) / 1e6; }

}  // namespace

nlohmann::ordered_json result_json(SegmentsModel& best, const runtime::mcmc::RunResult& run, const std::string& input) {
  const Scene& scene = best.scene();
  const auto& lines = scene.lines();
  const std::size_t n = lines.size();
  const SharedInput& sh = best.shared();
  const double explain = sh.explain;
  // Output order: by id.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return lines[x].id < lines[y].id; });
  std::vector<int> support(n, 0);
  double residual = 0.0;
  std::size_t explained = 0;
  for (std::size_t i = 0; i < scene.points().size(); ++i) {
    const int k = scene.nearest(i);
    if (k >= 0 && scene.distance(i) <= explain) {
      ++support[static_cast<std::size_t>(k)];
      residual += scene.distance(i);
      ++explained;
    }
  }
  const auto outcome = best.outcome();
  const auto& program = best.semantics().core().program();
  nlohmann::ordered_json segs = nlohmann::ordered_json::array();
  for (const std::size_t i : order) {
    const Line& l = lines[i];
    nlohmann::ordered_json probs = nlohmann::ordered_json::object();
    for (const std::int32_t q : best.semantics().core().queries()) {
      const auto& pred = program.predicates[static_cast<std::size_t>(q)];
      if (pred.arg_types.size() == 1) probs[pred.name] = r6(outcome->values[static_cast<std::size_t>(q)][i]);
    }
    segs.push_back({{"id", l.id},
                    {"a", {r4(l.seg.a.x), r4(l.seg.a.y)}},
                    {"b", {r4(l.seg.b.x), r4(l.seg.b.y)}},
                    {"length", r4(l.seg.length())},
                    {"support", support[i]},
                    {"probabilities", probs}});
  }
  // Binary predicates: query marginals > 0.5 and true evidence, over pairs a < b (by id).
  nlohmann::ordered_json relations = nlohmann::ordered_json::object();
  for (std::size_t p = 0; p < program.predicates.size(); ++p) {
    const auto& pred = program.predicates[p];
    if (pred.arg_types.size() != 2) continue;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (std::size_t x = 0; x < n; ++x)
      for (std::size_t y = x + 1; y < n; ++y) {
        const std::size_t a = order[x], b = order[y];
        const double v = std::max(outcome->values[p][a * n + b], outcome->values[p][b * n + a]);
        if (v > 0.5) list.push_back({lines[a].id, lines[b].id, r6(v)});
      }
    relations[pred.name] = {{"query", pred.query}, {"pairs", std::move(list)}};
  }
  const PriorParts& pp = best.prior_parts();
  const double secs = run.seconds;
  nlohmann::ordered_json metrics = {
      {"iterations", run.iterations},
      {"seconds", secs},
      {"iterations_per_second", secs > 0.0 ? static_cast<double>(run.iterations) / secs : 0.0},
      {"log_posterior", best.log_posterior()},
      {"log_likelihood", best.log_likelihood()},
      {"log_prior", best.log_prior()},
      {"log_prior_complexity", pp.complexity},
      {"log_prior_mln", pp.mln},
      {"log_prior_semantic", pp.semantic},
      {"best_iteration", run.best().best_iteration},
      {"segments", n},
      {"points", scene.points().size()},
      {"explained_points", explained},
      {"explained_fraction", scene.points().empty() ? 0.0 : static_cast<double>(explained) / static_cast<double>(scene.points().size())},
      {"mean_point_residual", explained ? residual / static_cast<double>(explained) : 0.0},
      {"candidates", sh.candidates},
      {"mln_method", outcome->method},
  };
  return {{"domain", sh.binding->domain},
          {"input", input},
          {"segments", std::move(segs)},
          {"relations", std::move(relations)},
          {"queries", best.semantics().queries_json(*outcome, best.constant_names())},
          {"metrics", std::move(metrics)}};
}

std::vector<unsigned char> overlay_png(const SegmentsModel& best, const nlohmann::ordered_json& result) {
  const auto& pts = best.scene().points();
  double x0 = pts[0].x, x1 = pts[0].x, y0 = pts[0].y, y1 = pts[0].y;
  for (const Vec2& p : pts) {
    x0 = std::min(x0, p.x); x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y); y1 = std::max(y1, p.y);
  }
  const double span = std::max({x1 - x0, y1 - y0, 1e-3});
  const int size = 800, margin = 20;
  const double scale = (size - 2 * margin) / span;
  const int w = static_cast<int>(std::ceil((x1 - x0) * scale)) + 2 * margin;
  const int h = static_cast<int>(std::ceil((y1 - y0) * scale)) + 2 * margin;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  auto px = [&](Vec2 p) {
    return cv::Point(static_cast<int>(std::lround((p.x - x0) * scale)) + margin,
                     h - 1 - (static_cast<int>(std::lround((p.y - y0) * scale)) + margin));
  };
  for (const Vec2& p : pts) cv::circle(img, px(p), 2, cv::Scalar(150, 150, 150), cv::FILLED, cv::LINE_AA);
  std::map<std::uint64_t, Segment> by_id;
  for (const Line& l : best.scene().lines()) by_id[l.id] = l.seg;
  const cv::Scalar palette[6] = {{200, 60, 30}, {40, 140, 40}, {30, 60, 200}, {160, 40, 160}, {20, 140, 180}, {90, 90, 20}};
  std::size_t c = 0;
  for (const auto& [id, s] : by_id) cv::line(img, px(s.a), px(s.b), palette[c++ % 6], 2, cv::LINE_AA);
  // Binary query relations: a ring at the meeting point of each pair, a colour per predicate.
  const cv::Scalar rings[4] = {{0, 0, 230}, {0, 170, 0}, {230, 0, 0}, {0, 140, 230}};
  std::size_t r = 0;
  for (const auto& item : result.at("relations").items()) {
    const auto& rel = item.value();
    if (!rel.at("query").get<bool>()) continue;
    const cv::Scalar ring = rings[r++ % 4];
    for (const auto& pair : rel.at("pairs")) {
      const Segment& s = by_id.at(pair[0].get<std::uint64_t>());
      const Segment& t = by_id.at(pair[1].get<std::uint64_t>());
      const Vec2 es[2] = {s.a, s.b}, ft[2] = {t.a, t.b};
      Vec2 best_p{};
      double bd = -1.0;
      for (const Vec2& e : es)
        for (const Vec2& f : ft)
          if (bd < 0.0 || dist(e, f) < bd) {
            bd = dist(e, f);
            best_p = 0.5 * (e + f);
          }
      cv::circle(img, px(best_p), 7, ring, 2, cv::LINE_AA);
    }
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", img, png)) throw std::runtime_error("overlay.png: PNG encoding failed");
  return png;
}

}  // namespace ksmc::stdlib::segments::kit
