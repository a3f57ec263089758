// The configuration a domain file gives its stdlib kit: every `model`, `extract`, `prior`,
// `likelihood`, `kernel` and `schedule` item of the `.ksm`, with each stdlib call's
// parameters checked by the compiler against the declared signature, defaults filled in,
// and numbers converted to base units (lengths in metres, angles in radians; `px` and
// `cells` as written). Generated `<domain>_model.cpp` builds one `DomainConfig` in source
// order; a stdlib kit (e.g. stdlib/tabletop, stdlib/indoor) reads it to assemble the model,
// kernels and schedule. A kit that meets a call it does not implement throws ConfigError
// naming the call's `file:line`.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "runtime/domain/config_error.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/program.h"

namespace ksmc::runtime::domain {

struct Value {
  enum class Kind { Number, Bool, String, Name, Index, List, Set, Call };
  Kind kind = Kind::Number;
  double number = 0.0;       // Number (base units)
  bool boolean = false;      // Bool
  std::string text;          // String contents, Name, Index collection (`pose`), Call function name
  std::vector<Value> items;  // Index: the index variable(s) as Names; List / Set items; Call arguments

  static Value num(double v) { Value x; x.kind = Kind::Number; x.number = v; return x; }
  static Value flag(bool b) { Value x; x.kind = Kind::Bool; x.boolean = b; return x; }
  static Value str(std::string s) { Value x; x.kind = Kind::String; x.text = std::move(s); return x; }
  static Value name(std::string s) { Value x; x.kind = Kind::Name; x.text = std::move(s); return x; }
  static Value index(std::string collection, std::vector<Value> vars) {
    Value x; x.kind = Kind::Index; x.text = std::move(collection); x.items = std::move(vars); return x;
  }
  static Value list(std::vector<Value> items) { Value x; x.kind = Kind::List; x.items = std::move(items); return x; }
  static Value set(std::vector<Value> items) { Value x; x.kind = Kind::Set; x.items = std::move(items); return x; }
  static Value call(std::string fn, std::vector<Value> args) {
    Value x; x.kind = Kind::Call; x.text = std::move(fn); x.items = std::move(args); return x;
  }
};

struct Arg {
  std::string name;  // the declared parameter name (positional arguments get theirs too)
  Value value;
};

// One stdlib call as written in the domain file, e.g. `obb.contact(pose[a], size[a], ...)`.
struct Call {
  std::string name;       // qualified: "obb.contact"
  std::vector<Arg> args;  // in declaration order of the signature, defaults filled in
  std::string where;      // "domains/tabletop.ksm:41"

  const Value* find(const std::string& param) const {
    for (const auto& a : args)
      if (a.name == param) return &a.value;
    return nullptr;
  }
  const Value& at(const std::string& param) const {
    if (const Value* v = find(param)) return *v;
    throw ConfigError(where + ": " + name + ": no parameter '" + param + "'");
  }
  double number(const std::string& param) const {
    const Value& v = at(param);
    if (v.kind != Value::Kind::Number) throw ConfigError(where + ": " + name + ": parameter '" + param + "' is not a number");
    return v.number;
  }
  // Checked numbers: a ConfigError naming the call's place when the value is out of range.
  double positive(const std::string& param) const {
    const double v = number(param);
    if (!(v > 0.0) || !std::isfinite(v)) fail(param, "must be positive, got " + show(v));
    return v;
  }
  double non_negative(const std::string& param) const {
    const double v = number(param);
    if (!(v >= 0.0) || !std::isfinite(v)) fail(param, "must be >= 0, got " + show(v));
    return v;
  }
  int whole(const std::string& param, int lo, int hi = std::numeric_limits<int>::max()) const {
    const double v = number(param);
    if (!(v >= lo && v <= hi) || v != std::floor(v))
      fail(param, "must be a whole number " +
                      (hi == std::numeric_limits<int>::max() ? ">= " + std::to_string(lo)
                                                              : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]") +
                      ", got " + show(v));
    return static_cast<int>(v);
  }
  bool flag(const std::string& param) const {
    const Value& v = at(param);
    if (v.kind != Value::Kind::Bool) throw ConfigError(where + ": " + name + ": parameter '" + param + "' is not true/false");
    return v.boolean;
  }

 private:
  [[noreturn]] void fail(const std::string& param, const std::string& what) const {
    throw ConfigError(where + ": " + name + ": parameter '" + param + "' " + what);
  }
  static std::string show(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
  }
};

// `pose[object] : se3 sampled;`, `unit[] : rect sampled;`
struct ModelVar {
  std::string name;
  bool collection = false;
  std::string index_type;  // "object"; empty for a variable-size collection or a scalar
  std::string value_type;  // "se3"
  bool sampled = false;
};

// `extract contact(a, b) = obb.contact(...);`
struct Extract {
  std::string predicate;
  std::vector<std::string> vars;
  Call call;
};

// `P(SaLe(a, b)) > 0.5` (probability of a query atom) or `Adj(a, b)` / `!Adj(a, b)`.
struct Condition {
  bool probability = false;
  bool negated = false;
  std::string predicate;
  std::vector<std::string> args;
  std::string op;  // > >= < <= (probability conditions)
  double threshold = 0.0;
};

// `prior mln;`, `prior rect_penalty(...);`, `prior for a, b where ...: gaussian(...);`
struct Prior {
  std::vector<std::string> vars;
  std::vector<Condition> conditions;
  Call call;
};

// One direction of a kernel declaration. A pair `kernel pair ADD / REMOVE = ...` gives two
// entries (ADD with reverse REMOVE, REMOVE with reverse ADD) sharing the sources.
struct Kernel {
  std::string name;
  std::string reverse;
  std::vector<std::pair<std::string, std::string>> params;  // (name, type): `refine(o: object)`
  std::vector<Call> sources;
  std::string where;
};

struct ScheduleRow {
  static constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();
  std::int64_t begin = 0;
  std::int64_t end = kForever;  // exclusive
  std::vector<std::pair<std::string, double>> probabilities;  // kernel name, selection probability
};

struct DomainConfig {
  std::string domain;
  std::string source;  // the domain file as given to ksmc
  std::vector<ModelVar> model;
  std::vector<Extract> extract;
  std::vector<Prior> prior;
  std::vector<Call> likelihood;
  std::vector<Kernel> kernels;
  std::vector<ScheduleRow> schedule;

  const Extract* extractor_of(const std::string& predicate) const {
    for (const auto& e : extract)
      if (e.predicate == predicate) return &e;
    return nullptr;
  }
};

// The generated Markov logic part of a domain (`<domain>_factors.h`), handed to the kit.
struct MlnBinding {
  const mln::Program& (*program)() = nullptr;
  mln::Domain (*make_domain)() = nullptr;
  mln::Grounding (*ground)(const mln::Domain&, const mln::Evidence&) = nullptr;
};

}  // namespace ksmc::runtime::domain
