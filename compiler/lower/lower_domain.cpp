#include "compiler/lower/lower_domain.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include "compiler/check/call_binding.h"
#include "compiler/check/rule_names.h"
#include "compiler/fmt/printer.h"
#include "compiler/lower/dump_ir.h"

namespace ksmc::compiler::lower {
namespace {

// Item offsets count code points (ANTLR decodes UTF-8); the source text is bytes.
std::size_t byte_offset(const std::string& text, std::size_t code_points) {
  std::size_t seen = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;  // continuation byte
    if (seen++ == code_points) return i;
  }
  return text.size();
}

// Variables of the item being lowered: name -> constant slot, and the kernel parameters.
struct Frame {
  std::map<std::string, int> slots;
  std::set<std::string> kernel_params;
};

class DomainLowerer {
 public:
  DomainLowerer(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources)
      : program_(program), main_(program.modules.front()), s_(symbols), sources_(sources) {}

  DomainIr run() {
    DomainIr ir;
    ir.domain = s_.domain;
    ir.source = main_.path;
    ir.kit = kit_of(program_, s_);
    ir.constant_type = check::constant_type(main_, s_);
    collect_prior_names();
    for (const ast::Item& item : main_.items) {
      if (const auto* m = std::get_if<ast::ModelDecl>(&item.node)) {
        ir.model_name = m->name.name;
        for (const ast::ModelVar& v : m->vars)
          ir.model.push_back({v.name.name, v.type.name, v.collection, v.index ? v.index->name : std::string(), v.sampled, v.loc});
      } else if (const auto* x = std::get_if<ast::ExtractDecl>(&item.node)) {
        ir.extracts.push_back(extract(*x, item));
      } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node)) {
        ir.priors.push_back(prior(*p, item));
      } else if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
        ir.likelihoods.push_back(ItemCallIr{call(l->call, {}), text(item), item.loc});
      } else if (const auto* o = std::get_if<ast::OutputDecl>(&item.node)) {
        ir.outputs.push_back(ItemCallIr{call(o->call, {}), text(item), item.loc});
      } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
        ir.kernels.push_back(kernel(*k, item));
      } else if (const auto* sd = std::get_if<ast::ScheduleDecl>(&item.node)) {
        for (const ast::ScheduleRow& r : sd->rows) ir.schedule.push_back(row(r));
      }
    }
    return ir;
  }

 private:
  std::string text(const ast::Item& item) const {
    const std::string& t = sources_.text(item.loc.file);
    const std::size_t begin = byte_offset(t, item.loc.offset);
    const std::size_t end = byte_offset(t, item.end_offset);
    if (begin >= t.size() || end <= begin) return {};
    return one_line(std::string_view(t).substr(begin, end - begin));
  }

  std::string pred_type(const std::string& pred, std::size_t arg) const {
    const check::PredicateSym* p = s_.predicate(pred);
    return p != nullptr && arg < p->decl->args.size() ? p->decl->args[arg].type.name : std::string();
  }

  // `prior_SaLe_gaussian`: the conditions' predicates and the term's name; a hash of the
  // term tells apart conditional priors that would otherwise share a name.
  static std::string prior_base(const ast::PriorDecl& p) {
    std::string s = "prior";
    for (const ast::Condition& c : p.conditions) s += "_" + c.atom.pred.name;
    s += "_" + p.call.name;
    for (char& ch : s)
      if (ch == '.') ch = '_';
    return s;
  }

  void collect_prior_names() {
    std::map<std::string, int> count;
    for (const ast::Item& item : main_.items)
      if (const auto* p = std::get_if<ast::PriorDecl>(&item.node); p != nullptr && p->quantified) ++count[prior_base(*p)];
    for (const ast::Item& item : main_.items) {
      const auto* p = std::get_if<ast::PriorDecl>(&item.node);
      if (p == nullptr || !p->quantified) continue;
      std::string name = prior_base(*p);
      if (count[name] > 1) {
        const std::uint32_t h = check::fnv1a(fmt::print_call(p->call));
        char hex[8];
        std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>((h ^ (h >> 16)) & 0xffffu));
        name += std::string("_") + hex;
      }
      prior_names_[p] = name;
    }
  }

  int constant_index(const std::string& type, const std::string& name) const {
    const check::TypeSym* t = s_.type(type);
    if (t == nullptr || t->domain == nullptr) return 0;
    for (std::size_t i = 0; i < t->domain->constants.size(); ++i)
      if (t->domain->constants[i].name == name) return static_cast<int>(i);
    return 0;
  }

  const ast::ModelVar* model_var(const std::string& name) const {
    auto it = s_.model_vars.find(name);
    return it == s_.model_vars.end() ? nullptr : it->second.decl;
  }

  // The value of expression `e` for a parameter of type `t` (list depth `depth` inside it).
  ValueIr value(const ast::Expr& e, const ast::TypeRef& t, const Frame& f) const {
    using K = ast::Expr::Kind;
    ValueIr v;
    v.loc = e.loc;
    v.written = fmt::print_expr(e);
    const bool is_int = t.name == "int" && !t.is_set;
    switch (e.kind) {
      case K::Number:
        if (is_int) {
          v.kind = ValueIr::Kind::Int;
          v.integer = static_cast<std::int64_t>(std::llround(e.number.value));
        } else {
          v.kind = ValueIr::Kind::Real;
          v.real = check::base_value(s_, e.number);
        }
        break;
      case K::Inf:
        v.kind = ValueIr::Kind::Real;
        v.real = std::numeric_limits<double>::infinity();
        break;
      case K::String:
        v.kind = ValueIr::Kind::String;
        v.text = e.text;
        break;
      case K::Bool:
        v.kind = ValueIr::Kind::Bool;
        v.flag = e.text == "true";
        break;
      case K::Name:
        if (auto slot = f.slots.find(e.text); slot != f.slots.end()) {
          v.kind = ValueIr::Kind::Entity;
          v.slot = slot->second;
        } else if (s_.predicate(e.text) != nullptr) {
          v.kind = ValueIr::Kind::Pred;
          v.text = e.text;
        } else if (const ast::ModelVar* mv = model_var(e.text)) {
          v.kind = mv->collection ? ValueIr::Kind::Collection : ValueIr::Kind::Scalar;
          v.text = e.text;
          v.type = mv->type.name;
        } else if (auto c = s_.constants.find(e.text); c != s_.constants.end()) {
          v.kind = ValueIr::Kind::Constant;
          v.text = e.text;
          v.type = c->second.type;
          v.slot = constant_index(c->second.type, e.text);
        }
        break;
      case K::Index: {
        const ast::ModelVar* mv = model_var(e.text);
        v.text = e.text;
        v.type = mv != nullptr ? mv->type.name : std::string();
        if (f.kernel_params.count(e.index.name) != 0) {
          v.kind = ValueIr::Kind::Dropped;
        } else {
          v.kind = ValueIr::Kind::Element;
          auto slot = f.slots.find(e.index.name);
          v.slot = slot != f.slots.end() ? slot->second : 0;
        }
        break;
      }
      case K::Call:
        v.kind = ValueIr::Kind::Call;
        v.call = std::make_shared<CallIr>(call(*e.call, f));
        break;
      case K::Set:
        v.kind = ValueIr::Kind::PredSet;
        for (const ast::Expr& item : e.items) v.preds.push_back(item.text);
        break;
      case K::List:
        v.kind = ValueIr::Kind::List;
        for (const ast::Expr& item : e.items) v.items.push_back(value(item, t, f));
        break;
    }
    return v;
  }

  CallIr call(const ast::Call& c, const Frame& f) const {
    CallIr ir;
    ir.block = c.name;
    ir.loc = c.loc;
    auto it = s_.externs.find(c.name);
    if (it == s_.externs.end()) return ir;
    const ast::ExternDecl& x = *it->second.decl;
    ir.kind = x.kind.name;
    if (x.result) ir.result = fmt::print_type(*x.result);
    ir.per_binding = ir.kind == "extractor" || ir.kind == "function" || (ir.kind == "prior" && x.result.has_value());
    for (const check::BoundArg& b : check::bind_call(c, x)) {
      if (b.value == nullptr) continue;
      ir.args.push_back(ArgIr{b.param->name.name, fmt::print_type(b.param->type), value(*b.value, b.param->type, f), b.defaulted});
    }
    return ir;
  }

  ExtractIr extract(const ast::ExtractDecl& x, const ast::Item& item) const {
    ExtractIr ir;
    ir.predicate = x.target.pred.name;
    Frame f;
    for (std::size_t i = 0; i < x.target.args.size(); ++i) {
      ir.vars.push_back(x.target.args[i].name);
      ir.var_types.push_back(pred_type(ir.predicate, i));
      f.slots[x.target.args[i].name] = static_cast<int>(i);
    }
    ir.call = call(x.call, f);
    ir.text = text(item);
    ir.loc = item.loc;
    return ir;
  }

  PriorIr prior(const ast::PriorDecl& p, const ast::Item& item) const {
    PriorIr ir;
    ir.conditional = p.quantified;
    ir.text = text(item);
    ir.loc = item.loc;
    Frame f;
    for (std::size_t i = 0; i < p.vars.size(); ++i) {
      ir.vars.push_back(p.vars[i].name);
      f.slots[p.vars[i].name] = static_cast<int>(i);
      std::string type;
      for (const ast::Condition& c : p.conditions)
        for (std::size_t a = 0; a < c.atom.args.size() && type.empty(); ++a)
          if (c.atom.args[a].name == p.vars[i].name) type = pred_type(c.atom.pred.name, a);
      ir.var_types.push_back(type.empty() ? check::constant_type(main_, s_) : type);
    }
    for (const ast::Condition& c : p.conditions) {
      ConditionIr k;
      k.probability = c.is_prob;
      k.predicate = c.atom.pred.name;
      for (const ast::Ident& a : c.atom.args) k.vars.push_back(f.slots.count(a.name) ? f.slots.at(a.name) : 0);
      k.op = c.is_prob ? c.op : std::string();
      k.threshold = c.is_prob ? c.threshold.value : 0.0;
      k.negated = c.negated;
      ir.conditions.push_back(std::move(k));
    }
    if (p.quantified) ir.function = prior_names_.at(&p);
    ir.call = call(p.call, f);
    return ir;
  }

  KernelIr kernel(const ast::KernelDecl& k, const ast::Item& item) const {
    KernelIr ir;
    ir.name = k.name.name;
    ir.reverse = k.reverse ? k.reverse->name : k.name.name;
    ir.pair = k.pair;
    Frame f;
    for (const ast::KernelParam& p : k.params) {
      ir.params.emplace_back(p.name.name, p.type.name);
      f.kernel_params.insert(p.name.name);
    }
    for (const ast::Call& c : k.sources) {
      ir.sources.push_back(call(c, f));
      auto it = s_.externs.find(c.name);
      if (it == s_.externs.end() || !ir.forward_move.empty()) continue;
      const ast::MoveSpec& m = it->second.decl->moves;
      if (m.kind != ast::MoveSpec::Kind::Makes || m.moves.empty()) continue;
      ir.forward_move = m.moves.front().name;
      ir.reverse_move = m.moves.back().name;
    }
    ir.text = text(item);
    ir.loc = item.loc;
    return ir;
  }

  static ScheduleRowIr row(const ast::ScheduleRow& r) {
    ScheduleRowIr ir;
    ir.loc = r.loc;
    ir.begin = r.has_range ? static_cast<std::int64_t>(std::llround(r.lo.value)) : 0;
    ir.forever = !r.has_range || r.hi_inf;
    ir.end = ir.forever ? 0 : static_cast<std::int64_t>(std::llround(r.hi.value));
    for (const ast::ScheduleEntry& e : r.entries) ir.probabilities.emplace_back(e.kernel.name, e.prob.value);
    return ir;
  }

  const ast::Program& program_;
  const ast::Module& main_;
  const check::SymbolTable& s_;
  const diag::SourceManager& sources_;
  std::map<const ast::PriorDecl*, std::string> prior_names_;
};

}  // namespace

std::string kit_of(const ast::Program& program, const check::SymbolTable& symbols) {
  for (const ast::Item& item : program.modules.front().items) {
    const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node);
    if (l == nullptr) continue;
    auto it = symbols.externs.find(l->call.name);
    if (it == symbols.externs.end()) return {};
    const std::string& path = program.modules.at(static_cast<std::size_t>(it->second.module)).path;
    const auto slash = path.find_last_of('/');
    const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash);
    const bool in_stdlib = dir == "stdlib" || (dir.size() > 7 && dir.compare(dir.size() - 7, 7, "/stdlib") == 0);
    if (!in_stdlib || file.size() < 5 || file.compare(file.size() - 4, 4, ".ksm") != 0) return {};
    return file.substr(0, file.size() - 4);
  }
  return {};
}

DomainIr lower_domain(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources) {
  return DomainLowerer(program, symbols, sources).run();
}

}  // namespace ksmc::compiler::lower
