#include "tools/mln_tabletop/labelled_world.h"

#include <set>
#include <stdexcept>
#include <vector>

#include "stdlib/tabletop/evidence.h"

namespace ksmc::tools::mln_tabletop {
namespace {

namespace tt = ksmc::stdlib::tabletop;

std::string constant(std::size_t body) { return body == 0 ? "Table" : "O" + std::to_string(body - 1); }

std::size_t body_of(const tt::Scene& scene, const std::string& id) {
  if (id == "table") return 0;
  const int i = scene.find(id);
  if (i < 0) throw std::runtime_error("the truth names object '" + id + "', which the scene does not have");
  return tt::Evidence::body(static_cast<std::size_t>(i));
}

}  // namespace

std::string labelled_world_db(const tt::Scene& scene, const nlohmann::json& truth, const std::string& comment) {
  const tt::Evidence ev = tt::extract_evidence(scene);
  const std::size_t n = ev.size();
  std::string out = "// " + comment + "\n// evidence (extracted from the estimated boxes)\n";
  auto unary = [&](const char* p, std::size_t a) { out += std::string(p) + "(" + constant(a) + ")\n"; };
  auto binary = [&](const char* p, std::size_t a, std::size_t b) {
    out += std::string(p) + "(" + constant(a) + ", " + constant(b) + ")\n";
  };
  for (std::size_t a = 0; a < n; ++a) {
    if (ev.is_table[a]) unary("table", a);
    if (ev.stable[a]) unary("stable", a);
    if (ev.hover[a]) unary("hover", a);
  }
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      if (ev.contact[a][b]) binary("contact", a, b);
      if (ev.intersect[a][b]) binary("intersect", a, b);
      if (ev.higher[a][b]) binary("higher", a, b);
    }
  std::set<std::size_t> supported, supportive, is_false, hidden;
  for (const auto& t : truth.at("objects")) {
    const std::size_t b = body_of(scene, t.at("id").get<std::string>());
    if (t.at("false").get<bool>()) is_false.insert(b);
    if (t.at("hidden").get<bool>()) hidden.insert(b);
  }
  for (const auto& e : truth.at("support")) {
    supported.insert(body_of(scene, e.at(0).get<std::string>()));
    supportive.insert(body_of(scene, e.at(1).get<std::string>()));
  }
  for (std::size_t a = 0; a < n; ++a)  // hard rule r10
    for (std::size_t b = 0; b < n; ++b)
      if (a != b && ev.stable[a] && ev.stable[b] && ev.contact[a][b] && ev.higher[a][b]) {
        supported.insert(a);
        supportive.insert(b);
      }
  out += "// labels (query atoms that are true; the others are false)\n";
  for (std::size_t a : supported) unary("supported", a);
  for (std::size_t a : supportive) unary("supportive", a);
  for (std::size_t a : hidden) unary("hidden", a);
  for (std::size_t a : is_false) unary("falseEst", a);
  return out;
}

}  // namespace ksmc::tools::mln_tabletop
