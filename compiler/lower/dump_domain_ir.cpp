#include "compiler/lower/dump_domain_ir.h"

#include <string>

#include "compiler/lower/dump_ir.h"

namespace ksmc::compiler::lower {
namespace {

class Dumper {
 public:
  Dumper(const diag::SourceManager& sources, std::ostream& out) : sources_(sources), out_(out) {}

  void run(const DomainIr& ir) {
    out_ << "domain " << ir.domain << " (" << ir.source << "), kit " << (ir.kit.empty() ? "-" : ir.kit)
         << ", constant type " << (ir.constant_type.empty() ? "-" : ir.constant_type) << "\n";
    if (!ir.model_name.empty()) out_ << "model " << ir.model_name << "\n";
    for (const ModelVarIr& v : ir.model) {
      out_ << "  var " << v.name << ": " << v.value_type;
      if (v.collection) out_ << "[" << v.index << "]";
      out_ << (v.sampled ? " sampled" : " fixed") << "  @" << at(v.loc) << "\n";
    }
    for (const ExtractIr& x : ir.extracts) {
      out_ << "extract " << x.predicate << "(" << vars(x.vars, x.var_types) << ")  @" << at(x.loc) << "\n";
      call(x.call, 1);
    }
    for (const PriorIr& p : ir.priors) {
      out_ << "prior";
      if (p.conditional) {
        out_ << " for " << vars(p.vars, p.var_types);
        for (std::size_t i = 0; i < p.conditions.size(); ++i) {
          const ConditionIr& c = p.conditions[i];
          out_ << (i ? " and " : " where ") << (c.negated ? "!" : "") << (c.probability ? "P(" : "") << c.predicate << "(";
          for (std::size_t a = 0; a < c.vars.size(); ++a) out_ << (a ? ", " : "") << "c" << c.vars[a];
          out_ << ")" << (c.probability ? ") " + c.op + " " + format_weight(c.threshold) : std::string());
        }
        out_ << " -> " << p.function;
      }
      out_ << "  @" << at(p.loc) << "\n";
      call(p.call, 1);
    }
    for (const ItemCallIr& l : ir.likelihoods) {
      out_ << "likelihood  @" << at(l.loc) << "\n";
      call(l.call, 1);
    }
    for (const ItemCallIr& o : ir.outputs) {
      out_ << "output  @" << at(o.loc) << "\n";
      call(o.call, 1);
    }
    for (const KernelIr& k : ir.kernels) {
      out_ << "kernel " << k.name << " reverse " << k.reverse << (k.pair ? " (pair)" : "");
      for (const auto& [n, t] : k.params) out_ << " " << n << ": " << t;
      out_ << " move " << (k.forward_move.empty() ? "?" : k.forward_move);
      if (k.name != k.reverse) out_ << " / " << (k.reverse_move.empty() ? "?" : k.reverse_move);
      out_ << "  @" << at(k.loc) << "\n";
      for (const CallIr& s : k.sources) call(s, 1);
    }
    for (const ScheduleRowIr& r : ir.schedule) {
      out_ << "schedule [" << r.begin << ", " << (r.forever ? std::string("inf") : std::to_string(r.end)) << "):";
      for (const auto& [k, p] : r.probabilities) out_ << " " << k << "=" << format_weight(p);
      out_ << "  @" << at(r.loc) << "\n";
    }
  }

 private:
  std::string at(const ast::Loc& loc) const {
    return sources_.path(loc.file) + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
  }

  static std::string vars(const std::vector<std::string>& names, const std::vector<std::string>& types) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
      s += (i ? ", " : "") + names[i] + ": " + (i < types.size() ? types[i] : std::string("?")) + " = c" + std::to_string(i);
    return s;
  }

  void call(const CallIr& c, int depth) {
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    out_ << indent << c.kind << " " << c.block << (c.per_binding ? " (per binding)" : "")
         << (c.result.empty() ? std::string() : " -> " + c.result) << "  @" << at(c.loc) << "\n";
    for (const ArgIr& a : c.args) {
      out_ << indent << "  " << a.param << ": " << a.type << " = " << value(a.value)
           << (a.defaulted ? "  (default " + a.value.written + ")" : "  (" + a.value.written + ")") << "\n";
      if (a.value.kind == ValueIr::Kind::Call && a.value.call) call(*a.value.call, depth + 2);
    }
  }

  static std::string value(const ValueIr& v) {
    using K = ValueIr::Kind;
    switch (v.kind) {
      case K::Real: return "real " + format_weight(v.real);
      case K::Int: return "int " + std::to_string(v.integer);
      case K::Bool: return std::string("bool ") + (v.flag ? "true" : "false");
      case K::String: return "string " + v.written;
      case K::Pred: return "pred " + v.text;
      case K::PredSet: {
        std::string s = "preds {";
        for (std::size_t i = 0; i < v.preds.size(); ++i) s += (i ? ", " : "") + v.preds[i];
        return s + "}";
      }
      case K::Entity: return "entity c" + std::to_string(v.slot);
      case K::Constant: return "constant " + v.type + " " + v.text + " = " + std::to_string(v.slot);
      case K::Element: return v.type + " " + v.text + "[c" + std::to_string(v.slot) + "]";
      case K::Collection: return v.type + "[] " + v.text;
      case K::Scalar: return v.type + " " + v.text;
      case K::Dropped: return "changed variable " + v.text + " (not passed)";
      case K::Call: return "call " + (v.call ? v.call->block : std::string("?"));
      case K::List: return "list " + bare(v);
    }
    return "?";
  }

  // A list without kind prefixes on its numbers: [[0.8, 0.1], [0.2, 0.9]].
  static std::string bare(const ValueIr& v) {
    if (v.kind == ValueIr::Kind::Real) return format_weight(v.real);
    if (v.kind == ValueIr::Kind::Int) return std::to_string(v.integer);
    if (v.kind != ValueIr::Kind::List) return value(v);
    std::string s = "[";
    for (std::size_t i = 0; i < v.items.size(); ++i) s += (i ? ", " : "") + bare(v.items[i]);
    return s + "]";
  }

  const diag::SourceManager& sources_;
  std::ostream& out_;
};

}  // namespace

void dump_domain_ir(const DomainIr& ir, const diag::SourceManager& sources, std::ostream& out) { Dumper(sources, out).run(ir); }

}  // namespace ksmc::compiler::lower
