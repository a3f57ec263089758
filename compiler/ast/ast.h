// The ksmc abstract syntax tree (output of compiler/build, input of compiler/check, fmt and
// the lowering pass).
//
// One `Module` per source file, one `Item` per top-level declaration, in source order. Nodes
// are plain structs that own their children by value (vectors) or unique_ptr; there are no
// parent pointers and no resolved symbols: name resolution lives in compiler/check/symbols.h.
// Every node that can be named in a diagnostic carries a `Loc`.
//
// Literal numbers keep their source spelling (`text`) so that `ksmc fmt` reproduces them
// exactly; `value` is the parsed double in the literal's own unit (no scaling — the unit's
// scale comes from the `quantity` declaration of the unit, see QuantityDecl).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace ksmc::compiler::ast {

// A position in a source file: file id from diag::SourceManager, 1-based line and column
// (columns count code points), and the 0-based code-point offset (fmt uses it to place
// comments; all offsets of one module are comparable).
struct Loc {
  int file = -1;
  int line = 0;
  int col = 0;
  std::size_t offset = 0;
};

struct Ident {
  std::string name;
  Loc loc;
};

// `3 mm`, `-0.5`, `1e-3`. `unit` is empty when the literal has none.
struct Number {
  double value = 0.0;
  std::string text;  // spelling without the unit, including a leading '-'
  bool integral = false;  // no '.' and no exponent in the spelling
  std::string unit;
  Loc loc;
  Loc unit_loc;
};

// `name: type`, `name: real[][]`, `name: real[3][3]`, `name: set<query>`, `name: query`.
struct TypeRef {
  std::string name;
  int list_depth = 0;     // number of trailing []
  std::vector<int> dims;  // per [ ]: its fixed size, 0 for variable (`[]`); size == list_depth
  bool is_set = false;    // set<name>
  Loc loc;
};

struct Call;

// Expressions appear only as call arguments and parameter defaults.
struct Expr {
  enum class Kind { Number, String, Bool, Inf, Name, Index, Call, List, Set };
  Kind kind = Kind::Number;
  Loc loc;
  Number number;              // Number
  std::string text;           // String (unescaped contents), Bool ("true"/"false"), Name, Index (collection)
  Ident index;                // Index: the variable inside [ ]
  std::shared_ptr<Call> call; // Call (shared so Expr stays copyable)
  std::vector<Expr> items;    // List, Set
};

struct Arg {
  std::optional<Ident> name;  // named argument when set
  Expr value;
};

// `obb.contact(pose[a], size[a], eps = 4 mm)` or a bare name such as `mln`.
struct Call {
  std::string name;  // qualified, dot-joined
  Loc loc;
  bool has_parens = false;
  std::vector<Arg> args;
};

// `contact(a, b)`: arguments are variables or constants of enumerated types.
struct Atom {
  Ident pred;
  std::vector<Ident> args;
};

struct Formula {
  enum class Kind { Atom, Not, And, Or, Implies, Iff, Exists };
  Kind kind = Kind::Atom;
  Loc loc;
  Atom atom;                      // Atom
  std::vector<Formula> children;  // Not: 1; And/Or: >= 2; Implies/Iff: 2 (lhs, rhs); Exists: 1
  std::vector<Ident> vars;        // Exists
};

// ---- top-level items -------------------------------------------------------------

struct DomainDecl { Ident name; };
struct IncludeDecl { std::string path; Loc loc; };

// `type object;` (constants supplied at run time) or `type kind = {A, B};` (enumerated).
struct TypeDecl {
  Ident name;
  bool enumerated = false;
  std::vector<Ident> constants;
};

struct PredArg {
  Ident type;
  bool exclusive = false;  // Alchemy's `p(x, t!)`: exactly one value of this argument is true
};
struct PredSig {
  Ident name;
  std::vector<PredArg> args;
};
// `evidence contact(object, object), higher(object, object);`
struct PredDecl {
  bool query = false;  // false: evidence
  std::vector<PredSig> preds;
};

// `quantity length [m = 1, cm = 0.01, mm = 0.001];` — a physical dimension and its units,
// each with its scale to the dimension's base unit.
struct UnitDef { Ident name; Number scale; };
struct QuantityDecl { Ident name; std::vector<UnitDef> units; };

// `value real, vec3, se3;` — opaque value types of the stdlib.
struct ValueDecl { std::vector<Ident> names; };

// `extern extractor obb.contact(pose_a: se3, ..., eps: length = 4 mm) -> bool;`
// One bound of `in [lo, hi]`: a number (with its unit) or `inf` / `-inf`.
struct Bound {
  bool inf = false;
  bool negative = false;  // -inf
  Number number;          // when !inf
  Loc loc;
};
// `in (0, inf)`, `in [1, 100]`, `in [0, 90 deg]`.
struct Range {
  bool lo_open = false;  // `(`
  bool hi_open = false;  // `)`
  Bound lo, hi;
  Loc loc;
};
struct Param {
  Ident name;
  TypeRef type;
  std::optional<Range> range;
  std::optional<Number> rowsum;  // `rowsum 1`
  Loc rowsum_loc;
  std::optional<Expr> default_value;
};
// `makes birth / death` (forward / reverse), `makes jitter` (self-reverse),
// `serves merge, interchange`.
struct MoveSpec {
  enum class Kind { None, Makes, Serves };
  Kind kind = Kind::None;
  std::vector<Ident> moves;  // Makes: 1 or 2; Serves: >= 1
  Loc loc;
};
struct ExternDecl {
  Ident kind;  // extractor | prior | likelihood | proposal | function | output
  std::string name;
  Loc name_loc;
  bool has_params = false;
  std::vector<Param> params;
  std::optional<TypeRef> result;
  std::optional<TypeRef> reads;  // `reads rect[]`
  MoveSpec moves;
};

// `extern model(rect[] sampled, segment[] sampled);` — the model a kit runs: per variable
// its value type, indexing (`[]` variable-size, `[entity]` one per run-time constant, none
// for a scalar) and sampled / fixed.
struct ModelSlot {
  Ident type;
  bool collection = false;
  std::optional<Ident> index;
  bool sampled = false;
  Loc loc;
};
struct ModelContractDecl { std::vector<ModelSlot> slots; };

struct Rule {
  std::optional<Ident> label;    // `@name`
  bool hard = false;
  std::optional<Number> prob;    // `prob p:` (weight log(p/(1-p)))
  std::optional<Number> weight;  // `w x:`
  Loc head_loc;                  // first token of the rule (after `@name`)
  bool exactly_one = false;      // `exactly one of a, b, c`
  std::vector<Atom> alternatives;
  Formula formula;               // when !exactly_one
  std::string source_text;       // the rule as written, without `@name` (comments in generated code)
};

// Inside `model NAME { ... }`: `pose[object] : se3 sampled;`, `unit[] : rect sampled;`
// (variable-size collection; when a type of the same name exists, the collection's
// elements are that type's constants), `table_pose : se3 fixed;` (scalar).
struct ModelVar {
  Ident name;
  bool collection = false;      // has [ ]
  std::optional<Ident> index;   // index type inside [ ], absent for variable-size
  TypeRef type;
  bool sampled = false;
  Loc loc;
  std::size_t end_offset = 0;
  int end_line = 0;
};
struct ModelDecl { Ident name; std::vector<ModelVar> vars; };

struct ExtractDecl { Atom target; Call call; };

struct Condition {
  bool is_prob = false;  // P(atom) op threshold
  Ident fn;              // `P`
  Atom atom;
  bool negated = false;  // atom condition
  std::string op;        // > >= < <=
  Number threshold;
};
// `prior mln;`, `prior rect_penalty(psi1 = 1);`,
// `prior for a, b where P(SaLe(a, b)) > 0.5: gaussian(...);`
struct PriorDecl {
  bool quantified = false;
  std::vector<Ident> vars;
  std::vector<Condition> conditions;
  Call call;
};

struct LikelihoodDecl { Call call; };

// `output scene.decisions(false_est = falseEst, hidden = hidden);`
struct OutputDecl { Call call; };

// `kernel pair ADD / REMOVE = detect.wbu(...), detect.fsu(after = 4000);`
// `kernel refine(o: object) reverse refine = pose.perturb(pose[o], ...);`
struct KernelParam { Ident name; Ident type; };
struct KernelDecl {
  bool pair = false;
  Ident name;
  std::optional<Ident> reverse;  // pair: the second name; single: `reverse NAME`
  std::vector<KernelParam> params;
  std::vector<Call> sources;     // proposal sources / moves, in order
};

struct ScheduleEntry { Ident kernel; Number prob; };
struct ScheduleRow {
  bool has_range = false;  // a row without range covers [0, inf)
  Number lo;
  bool hi_inf = true;
  Number hi;
  std::vector<ScheduleEntry> entries;
  Loc loc;
  std::size_t end_offset = 0;
  int end_line = 0;
};
struct ScheduleDecl { std::vector<ScheduleRow> rows; };

using ItemNode = std::variant<DomainDecl, IncludeDecl, TypeDecl, PredDecl, QuantityDecl,
                              ValueDecl, ExternDecl, Rule, ModelDecl, ExtractDecl, PriorDecl,
                              LikelihoodDecl, KernelDecl, ScheduleDecl, ModelContractDecl, OutputDecl>;

struct Item {
  Loc loc;                     // first token
  std::size_t end_offset = 0;  // byte offset just past the last token
  int end_line = 0;
  ItemNode node;
};

struct Comment {
  Loc loc;
  std::size_t end_offset = 0;
  std::string text;  // as written, including // or /* */
};

struct Module {
  int file = -1;
  std::string path;  // as given / as resolved for includes
  std::vector<Item> items;
  std::vector<Comment> comments;  // in source order
};

// All modules of one compilation: modules[0] is the file named on the command line,
// the others are its (transitive) includes, each loaded once.
struct Program {
  std::vector<Module> modules;
};

}  // namespace ksmc::compiler::ast
