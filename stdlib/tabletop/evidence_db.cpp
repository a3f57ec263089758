#include "stdlib/tabletop/evidence_db.h"

#include <stdexcept>

#include <fmt/format.h>

namespace ksmc::stdlib::tabletop {

namespace {

bool valid_db_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

void line(std::string& out, bool value, const char* pred, const std::string& a) {
  out += fmt::format("{}{}({})\n", value ? "" : "!", pred, a);
}
void line(std::string& out, bool value, const char* pred, const std::string& a, const std::string& b) {
  out += fmt::format("{}{}({}, {})\n", value ? "" : "!", pred, a, b);
}

}  // namespace

std::string evidence_db(const Evidence& ev) {
  for (const auto& id : ev.ids)
    if (!valid_db_name(id))
      throw std::invalid_argument(fmt::format("evidence_db: id \"{}\" is not a valid .db constant "
                                              "(letters, digits, '_', '-', '.')", id));
  const std::size_t n = ev.size();
  std::string out = "// table-top evidence (closed world)\n";
  for (std::size_t i = 0; i < n; ++i) line(out, ev.is_table[i], "table", ev.ids[i]);
  for (std::size_t i = 0; i < n; ++i) line(out, ev.stable[i], "stable", ev.ids[i]);
  for (std::size_t i = 0; i < n; ++i) line(out, ev.hover[i], "hover", ev.ids[i]);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) line(out, a != b && ev.contact[a][b], "contact", ev.ids[a], ev.ids[b]);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) line(out, a != b && ev.intersect[a][b], "intersect", ev.ids[a], ev.ids[b]);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) line(out, a != b && ev.higher[a][b], "higher", ev.ids[a], ev.ids[b]);
  return out;
}

}  // namespace ksmc::stdlib::tabletop
