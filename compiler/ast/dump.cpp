#include "compiler/ast/dump.h"

#include <string>

namespace ksmc::compiler::ast {

namespace {

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '\t') {
      out += "\\t";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string num(const Number& n) { return n.unit.empty() ? n.text : n.text + " " + n.unit; }

std::string type_ref(const TypeRef& t) {
  if (t.is_set) return "set<" + t.name + ">";
  std::string s = t.name;
  for (int i = 0; i < t.list_depth; ++i) {
    const int n = i < static_cast<int>(t.dims.size()) ? t.dims[static_cast<std::size_t>(i)] : 0;
    s += n > 0 ? "[" + std::to_string(n) + "]" : std::string("[]");
  }
  return s;
}

std::string atom(const Atom& a) {
  std::string s = "(" + a.pred.name;
  for (const Ident& x : a.args) s += " " + x.name;
  return s + ")";
}

std::string call(const Call& c);

std::string expr(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Number: return "(num " + num(e.number) + ")";
    case Expr::Kind::String: return "(str " + quote(e.text) + ")";
    case Expr::Kind::Bool: return "(bool " + e.text + ")";
    case Expr::Kind::Inf: return "(inf)";
    case Expr::Kind::Name: return "(name " + e.text + ")";
    case Expr::Kind::Index: return "(index " + e.text + " " + e.index.name + ")";
    case Expr::Kind::Call: return call(*e.call);
    case Expr::Kind::List:
    case Expr::Kind::Set: {
      std::string s = e.kind == Expr::Kind::List ? "(list" : "(set";
      for (const Expr& i : e.items) s += " " + expr(i);
      return s + ")";
    }
  }
  return "(?)";
}

std::string call(const Call& c) {
  std::string s = "(call " + c.name + (c.has_parens ? " ()" : "");
  for (const Arg& a : c.args) s += a.name ? " (" + a.name->name + " = " + expr(a.value) + ")" : " " + expr(a.value);
  return s + ")";
}

std::string formula(const Formula& f) {
  switch (f.kind) {
    case Formula::Kind::Atom: return atom(f.atom);
    case Formula::Kind::Not: return "(not " + formula(f.children[0]) + ")";
    case Formula::Kind::Exists: {
      std::string s = "(exists (";
      for (std::size_t i = 0; i < f.vars.size(); ++i) s += (i ? " " : "") + f.vars[i].name;
      return s + ") " + formula(f.children[0]) + ")";
    }
    default: {
      const char* op = f.kind == Formula::Kind::And ? "and" : f.kind == Formula::Kind::Or ? "or"
                       : f.kind == Formula::Kind::Implies                                  ? "=>"
                                                                                           : "<=>";
      std::string s = std::string("(") + op;
      for (const Formula& c : f.children) s += " " + formula(c);
      return s + ")";
    }
  }
}

struct Dumper {
  std::ostream& out;

  void operator()(const DomainDecl& d) { out << "(domain " << d.name.name << ")"; }
  void operator()(const IncludeDecl& i) { out << "(include " << quote(i.path) << ")"; }
  void operator()(const TypeDecl& t) {
    out << "(type " << t.name.name;
    if (t.enumerated) {
      out << " (";
      for (std::size_t i = 0; i < t.constants.size(); ++i) out << (i ? " " : "") << t.constants[i].name;
      out << ")";
    }
    out << ")";
  }
  void operator()(const PredDecl& d) {
    out << (d.query ? "(query" : "(evidence");
    for (const PredSig& p : d.preds) {
      out << " (" << p.name.name;
      for (const PredArg& a : p.args) out << " " << a.type.name << (a.exclusive ? "!" : "");
      out << ")";
    }
    out << ")";
  }
  void operator()(const QuantityDecl& q) {
    out << "(quantity " << q.name.name;
    for (const UnitDef& u : q.units) out << " (" << u.name.name << " " << num(u.scale) << ")";
    out << ")";
  }
  void operator()(const ValueDecl& v) {
    out << "(value";
    for (const Ident& n : v.names) out << " " << n.name;
    out << ")";
  }
  void operator()(const ExternDecl& x) {
    out << "(extern " << x.kind.name << " " << x.name;
    if (x.has_params) {
      out << " (params";
      for (const Param& p : x.params) {
        out << " (" << p.name.name << " " << type_ref(p.type);
        if (p.range) out << " (in " << bound(p.range->lo, p.range->lo_open ? "(" : "[") << ", " << bound(p.range->hi, "") << (p.range->hi_open ? ")" : "]") << ")";
        if (p.rowsum) out << " (rowsum " << num(*p.rowsum) << ")";
        if (p.default_value) out << " " << expr(*p.default_value);
        out << ")";
      }
      out << ")";
    }
    if (x.result) out << " (result " << type_ref(*x.result) << ")";
    if (x.reads) out << " (reads " << type_ref(*x.reads) << ")";
    if (x.moves.kind != MoveSpec::Kind::None) {
      out << (x.moves.kind == MoveSpec::Kind::Makes ? " (makes" : " (serves");
      for (const Ident& m : x.moves.moves) out << " " << m.name;
      out << ")";
    }
    out << ")";
  }
  std::string bound(const Bound& b, const char* open) {
    return std::string(open) + (b.inf ? (b.negative ? "-inf" : "inf") : num(b.number));
  }
  void operator()(const ModelContractDecl& d) {
    out << "(extern model";
    for (const ModelSlot& s : d.slots) {
      out << " (" << s.type.name;
      if (s.collection) out << (s.index ? " [" + s.index->name + "]" : std::string(" []"));
      out << (s.sampled ? " sampled" : " fixed") << ")";
    }
    out << ")";
  }
  void operator()(const OutputDecl& o) { out << "(output " << call(o.call) << ")"; }
  void operator()(const Rule& r) {
    out << "(rule";
    if (r.label) out << " @" << r.label->name;
    if (r.hard) out << " hard";
    if (r.prob) out << " (prob " << num(*r.prob) << ")";
    if (r.weight) out << " (w " << num(*r.weight) << ")";
    if (r.exactly_one) {
      out << " (exactly-one";
      for (const Atom& a : r.alternatives) out << " " << atom(a);
      out << ")";
    } else {
      out << " " << formula(r.formula);
    }
    out << ")";
  }
  void operator()(const ModelDecl& m) {
    out << "(model " << m.name.name;
    for (const ModelVar& v : m.vars) {
      out << "\n  (var " << v.name.name;
      if (v.collection) out << (v.index ? " [" + v.index->name + "]" : std::string(" []"));
      out << " " << type_ref(v.type) << (v.sampled ? " sampled" : " fixed") << ")";
    }
    out << ")";
  }
  void operator()(const ExtractDecl& e) { out << "(extract " << atom(e.target) << " " << call(e.call) << ")"; }
  void operator()(const PriorDecl& p) {
    out << "(prior";
    if (p.quantified) {
      out << " (for";
      for (const Ident& v : p.vars) out << " " << v.name;
      out << ")";
      for (const Condition& c : p.conditions) {
        if (c.is_prob) {
          out << " (where " << c.fn.name << " " << atom(c.atom) << " " << c.op << " " << num(c.threshold) << ")";
        } else {
          out << " (where " << (c.negated ? "!" : "") << atom(c.atom) << ")";
        }
      }
    }
    out << " " << call(p.call) << ")";
  }
  void operator()(const LikelihoodDecl& l) { out << "(likelihood " << call(l.call) << ")"; }
  void operator()(const KernelDecl& k) {
    out << "(kernel" << (k.pair ? " pair " : " ") << k.name.name;
    if (k.reverse) out << (k.pair ? " / " : " reverse ") << k.reverse->name;
    if (!k.params.empty()) {
      out << " (params";
      for (const KernelParam& p : k.params) out << " (" << p.name.name << " " << p.type.name << ")";
      out << ")";
    }
    for (const Call& c : k.sources) out << "\n  " << call(c);
    out << ")";
  }
  void operator()(const ScheduleDecl& s) {
    out << "(schedule";
    for (const ScheduleRow& r : s.rows) {
      out << "\n  (row";
      if (r.has_range) out << " [" << num(r.lo) << ", " << (r.hi_inf ? std::string("inf") : num(r.hi)) << ")";
      for (const ScheduleEntry& e : r.entries) out << " (" << e.kernel.name << " " << num(e.prob) << ")";
      out << ")";
    }
    out << ")";
  }
};

}  // namespace

void dump(const Module& m, std::ostream& out) {
  Dumper d{out};
  for (const Item& item : m.items) {
    std::visit(d, item.node);
    out << '\n';
  }
}

}  // namespace ksmc::compiler::ast
