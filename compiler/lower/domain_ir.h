// The typed domain IR: the sampler half of a checked domain file (model, extract, prior,
// likelihood, outputs, kernels with their move, schedule) with every stdlib call resolved to
// its `extern` signature and its arguments bound once, in signature order, defaults filled
// in, numbers converted to base units, names resolved (predicates, entity variables, model
// variables). `ksmc emit` generates the binding from it (compiler/emit/emit_model.h);
// `ksmc --dump-domain-ir` prints it (compiler/lower/dump_domain_ir.h).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compiler/ast/ast.h"

namespace ksmc::compiler::lower {

struct CallIr;

// One bound argument value.
struct ValueIr {
  enum class Kind {
    Real,        // `real` or a quantity, in base units (may be +-inf)
    Int,         // `int`
    Bool,
    String,
    Pred,        // a predicate (`query` / `evidence` / `pred` parameter): `text`
    PredSet,     // `set<...>` of predicates: `preds`
    Entity,      // an entity variable: the binding's constant `slot`
    Constant,    // a constant `text` of enumerated type `type`: its index `slot` within the type
    Element,     // `x[v]`: element `slot` of model variable `text`, of value type `type`
    Collection,  // a whole variable-size model collection `text` of value type `type`
    Scalar,      // a scalar model variable `text` of value type `type`
    Dropped,     // proposal argument `x[k]` indexed by a kernel parameter: names the changed variable
    Call,        // a function call
    List,        // `items`
  };
  Kind kind = Kind::Real;
  double real = 0.0;
  std::int64_t integer = 0;
  bool flag = false;
  std::string text;
  std::string type;
  int slot = -1;
  std::vector<std::string> preds;
  std::vector<ValueIr> items;
  std::shared_ptr<CallIr> call;
  std::string written;  // the source spelling
  ast::Loc loc;
};

struct ArgIr {
  std::string param;  // parameter name
  std::string type;   // parameter type as declared, e.g. "real[3][3]"
  ValueIr value;
  bool defaulted = false;
};

// A call of an `extern` block with its arguments bound.
struct CallIr {
  std::string block;        // qualified name, e.g. "geom.room_like"
  std::string kind;         // extractor | prior | likelihood | proposal | function | output
  bool per_binding = false; // takes the scene (extractors, functions, `-> real` priors)
  std::string result;       // declared result type, empty for none
  std::vector<ArgIr> args;  // signature order
  ast::Loc loc;
};

struct ModelVarIr {
  std::string name;
  std::string value_type;
  bool collection = false;
  std::string index;  // collection index type; empty for variable-size collections
  bool sampled = false;
  ast::Loc loc;
};

struct ExtractIr {
  std::string predicate;
  std::vector<std::string> vars;       // constant slots 0, 1, ...
  std::vector<std::string> var_types;
  CallIr call;
  std::string text;  // the item as written, one line
  ast::Loc loc;
};

struct ConditionIr {
  bool probability = false;  // P(atom) op threshold; else an evidence atom
  std::string predicate;
  std::vector<int> vars;     // indices into PriorIr::vars
  std::string op;            // > >= < <=
  double threshold = 0.0;
  bool negated = false;
};

// `prior name(...);` (global term) or `prior for VARS where ...: term(...);`.
struct PriorIr {
  bool conditional = false;
  std::string function;                 // conditional: name of the generated term function
  std::vector<std::string> vars, var_types;
  std::vector<ConditionIr> conditions;
  CallIr call;
  std::string text;
  ast::Loc loc;
};

// A likelihood or output item.
struct ItemCallIr {
  CallIr call;
  std::string text;
  ast::Loc loc;
};

struct KernelIr {
  std::string name;
  std::string reverse;  // == name for a self-reverse kernel
  bool pair = false;
  std::vector<std::pair<std::string, std::string>> params;  // name, type
  std::string forward_move;  // the move the sources make (`makes F / R`: F; `makes M`: M)
  std::string reverse_move;  // R, or M for a self-reverse move
  std::vector<CallIr> sources;
  std::string text;
  ast::Loc loc;
};

struct ScheduleRowIr {
  std::int64_t begin = 0;
  std::int64_t end = 0;
  bool forever = true;  // end is infinite
  std::vector<std::pair<std::string, double>> probabilities;
  ast::Loc loc;
};

struct DomainIr {
  std::string domain;
  std::string source;         // the domain file as given
  std::string kit;            // the stdlib kit (package of the likelihood's declaration)
  std::string constant_type;  // the kit's run-time constant type
  std::string model_name;
  std::vector<ModelVarIr> model;
  std::vector<ExtractIr> extracts;
  std::vector<PriorIr> priors;  // source order, global and conditional
  std::vector<ItemCallIr> likelihoods;  // source order; several are factors of one likelihood
  std::vector<ItemCallIr> outputs;
  std::vector<KernelIr> kernels;
  std::vector<ScheduleRowIr> schedule;
};

}  // namespace ksmc::compiler::lower
