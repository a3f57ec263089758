// segments_check RESULT.json TRUTH.json
// Checks a segments.json of bin/segments against a ground truth (examples/segments/
// room_truth.json): every true segment is matched by a distinct fitted one (both endpoints
// within distance_m, direction within angle_deg), at most max_spurious fitted segments are
// unmatched, and every true corner is a Corner pair of the matched segments. Prints the
// matching; exit status 0 when all hold, 1 otherwise, 2 on unreadable files.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

struct Seg {
  double ax, ay, bx, by;
  std::uint64_t id = 0;
};

double d(double x1, double y1, double x2, double y2) { return std::hypot(x1 - x2, y1 - y2); }

// max endpoint distance under the best pairing of endpoints
double endpoint_error(const Seg& s, const Seg& t) {
  const double same = std::max(d(s.ax, s.ay, t.ax, t.ay), d(s.bx, s.by, t.bx, t.by));
  const double swap = std::max(d(s.ax, s.ay, t.bx, t.by), d(s.bx, s.by, t.ax, t.ay));
  return std::min(same, swap);
}

double angle_deg(const Seg& s, const Seg& t) {
  const double a1 = std::atan2(s.by - s.ay, s.bx - s.ax), a2 = std::atan2(t.by - t.ay, t.bx - t.ax);
  double diff = std::fmod(std::abs(a1 - a2), M_PI);
  if (diff > M_PI / 2) diff = M_PI - diff;
  return diff * 180.0 / M_PI;
}

nlohmann::json read(const char* path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(std::string(path) + ": cannot open");
  return nlohmann::json::parse(in);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: segments_check RESULT.json TRUTH.json\n";
    return 2;
  }
  nlohmann::json result, truth;
  try {
    result = read(argv[1]);
    truth = read(argv[2]);
  } catch (const std::exception& e) {
    std::cerr << "segments_check: " << e.what() << "\n";
    return 2;
  }
  std::vector<Seg> fitted, real;
  for (const auto& s : result.at("segments"))
    fitted.push_back({s.at("a")[0].get<double>(), s.at("a")[1].get<double>(), s.at("b")[0].get<double>(),
                      s.at("b")[1].get<double>(), s.at("id").get<std::uint64_t>()});
  for (const auto& s : truth.at("segments"))
    real.push_back({s[0].get<double>(), s[1].get<double>(), s[2].get<double>(), s[3].get<double>()});
  const auto& tol = truth.at("tolerances");
  const double max_dist = tol.at("distance_m").get<double>();
  const double max_angle = tol.at("angle_deg").get<double>();
  const std::size_t max_spurious = tol.at("max_spurious").get<std::size_t>();

  bool ok = true;
  std::vector<int> match(real.size(), -1);
  std::set<std::size_t> used;
  for (std::size_t t = 0; t < real.size(); ++t) {
    double best = 1e300;
    for (std::size_t f = 0; f < fitted.size(); ++f) {
      if (used.count(f) || angle_deg(real[t], fitted[f]) > max_angle) continue;
      const double e = endpoint_error(real[t], fitted[f]);
      if (e <= max_dist && e < best) {
        best = e;
        match[t] = static_cast<int>(f);
      }
    }
    if (match[t] >= 0) {
      used.insert(static_cast<std::size_t>(match[t]));
      std::cout << "true segment " << t << ": matched by id " << fitted[static_cast<std::size_t>(match[t])].id
                << " (endpoint error " << best << " m)\n";
    } else {
      std::cout << "true segment " << t << ": NOT matched\n";
      ok = false;
    }
  }
  const std::size_t spurious = fitted.size() - used.size();
  std::cout << "fitted " << fitted.size() << ", spurious " << spurious << " (at most " << max_spurious << ")\n";
  if (spurious > max_spurious) ok = false;
  std::set<std::pair<std::uint64_t, std::uint64_t>> corners;
  if (result.at("relations").contains("Corner"))
    for (const auto& p : result["relations"]["Corner"]["pairs"]) {
      const auto a = p[0].get<std::uint64_t>(), b = p[1].get<std::uint64_t>();
      corners.insert({std::min(a, b), std::max(a, b)});
    }
  for (const auto& c : truth.at("corners")) {
    const auto i = c[0].get<std::size_t>(), j = c[1].get<std::size_t>();
    bool found = false;
    if (match.at(i) >= 0 && match.at(j) >= 0) {
      const auto a = fitted[static_cast<std::size_t>(match[i])].id, b = fitted[static_cast<std::size_t>(match[j])].id;
      found = corners.count({std::min(a, b), std::max(a, b)}) > 0;
    }
    std::cout << "corner " << i << "-" << j << ": " << (found ? "found" : "MISSING") << "\n";
    ok = ok && found;
  }
  std::cout << (ok ? "PASS" : "FAIL") << "\n";
  return ok ? 0 : 1;
}
