// Loading evidence for the tests: the domain taken from the .db text (Alchemy style)
// and the evidence parsed from it.
#pragma once

#include <memory>
#include <string>

#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace ksmc::tests::mln {

struct Scene {
  runtime::mln::Domain domain;
  std::unique_ptr<runtime::mln::Evidence> evidence;
};

inline Scene scene_from_text(const runtime::mln::Program& program, const std::string& text,
                             const std::string& name) {
  Scene s;
  runtime::mln::collect_db_constants(text, name, program, s.domain);
  s.evidence = std::make_unique<runtime::mln::Evidence>(program, s.domain);
  runtime::mln::parse_db(text, name, program, s.domain, *s.evidence);
  return s;
}

// A scene of tests/mln/data (e.g. "scene20.db").
inline Scene data_scene(const runtime::mln::Program& program, const std::string& file) {
  const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/" + file;
  return scene_from_text(program, runtime::mln::read_text_file(path), path);
}

}  // namespace ksmc::tests::mln
