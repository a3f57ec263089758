#include "compiler/build/builder.h"

#include <antlr4-runtime.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "KsmLexer.h"
#include "KsmParser.h"

namespace ksmc::compiler::build {

namespace {

using P = ksmc_grammar::KsmParser;

class Builder {
 public:
  Builder(const parse::ParsedFile& parsed, diag::DiagEngine& diags) : parsed_(parsed), diags_(diags) {}

  ast::Module run(const std::string& path) {
    ast::Module m;
    m.file = parsed_.file;
    m.path = path;
    auto* tree = static_cast<P::FileContext*>(parsed_.tree);
    for (P::ItemContext* ic : tree->item()) {
      ast::Item item;
      item.loc = loc(ic->getStart());
      const antlr4::Token* stop = ic->getStop();
      item.end_offset = stop != nullptr ? stop->getStopIndex() + 1 : item.loc.offset;
      item.end_line = stop != nullptr ? static_cast<int>(stop->getLine()) : item.loc.line;
      if (!build_item(ic, item)) continue;
      m.items.push_back(std::move(item));
    }
    for (antlr4::Token* t : parsed_.tokens->getTokens()) {
      if (t->getType() == P::LINE_COMMENT || t->getType() == P::BLOCK_COMMENT) {
        m.comments.push_back(ast::Comment{loc(t), t->getStopIndex() + 1, t->getText()});
      }
    }
    return m;
  }

 private:
  ast::Loc loc(const antlr4::Token* t) const {
    return ast::Loc{parsed_.file, static_cast<int>(t->getLine()), static_cast<int>(t->getCharPositionInLine()) + 1,
                    t->getStartIndex()};
  }
  ast::Loc loc(antlr4::tree::TerminalNode* n) const { return loc(n->getSymbol()); }
  ast::Loc loc(antlr4::ParserRuleContext* c) const { return loc(c->getStart()); }
  ast::Ident ident(antlr4::tree::TerminalNode* n) const { return ast::Ident{n->getText(), loc(n)}; }
  ast::Ident ident(antlr4::Token* t) const { return ast::Ident{t->getText(), loc(t)}; }

  std::string source_text(antlr4::ParserRuleContext* c) const {
    if (c->getStart() == nullptr || c->getStop() == nullptr) return {};
    return parsed_.input->getText(antlr4::misc::Interval(c->getStart()->getStartIndex(), c->getStop()->getStopIndex()));
  }

  ast::Number number(P::NumberContext* c) {
    ast::Number n;
    n.loc = loc(c);
    const bool neg = c->getStart()->getText() == "-";
    n.text = (neg ? "-" : "") + c->NUMBER()->getText();
    n.integral = n.text.find_first_of(".eE") == std::string::npos;
    n.value = std::strtod(n.text.c_str(), nullptr);
    if (!std::isfinite(n.value)) {
      diags_.error(n.loc, "number '" + n.text + "' is out of range");
      n.value = 0.0;
    }
    if (c->unit != nullptr) {
      n.unit = c->unit->getText();
      n.unit_loc = loc(c->unit);
    }
    return n;
  }

  ast::TypeRef type_ref(P::TypeRefContext* c) {
    ast::TypeRef t;
    t.loc = loc(c);
    if (auto* s = dynamic_cast<P::SetTypeContext*>(c)) {
      t.is_set = true;
      t.name = s->elem->getText();
    } else if (auto* n = dynamic_cast<P::NamedTypeContext*>(c)) {
      t.name = n->name->getText();
      for (P::DimContext* d : n->dim()) {
        int size = 0;
        if (d->NUMBER() != nullptr) {
          const std::string text = d->NUMBER()->getText();
          const double v = std::strtod(text.c_str(), nullptr);
          if (text.find_first_of(".eE") != std::string::npos || v < 1 || v > 1e6) {
            diags_.error(loc(d->NUMBER()), "list size '" + text + "' must be a whole number from 1 to 1000000");
          } else {
            size = static_cast<int>(v);
          }
        }
        t.dims.push_back(size);
      }
      t.list_depth = static_cast<int>(t.dims.size());
    }
    return t;
  }

  ast::Bound bound(P::BoundContext* c) {
    ast::Bound b;
    b.loc = loc(c);
    if (c->number() != nullptr) {
      b.number = number(c->number());
    } else {
      b.inf = true;
      b.negative = c->neg != nullptr;
    }
    return b;
  }

  ast::Param param(P::ParamContext* pc) {
    ast::Param p;
    p.name = ident(pc->IDENT());
    p.type = type_ref(pc->typeRef());
    if (auto* r = pc->paramRange()) {
      ast::Range range;
      range.loc = loc(r);
      range.lo_open = r->lo->getText() == "(";
      range.hi_open = r->hi->getText() == ")";
      range.lo = bound(r->lower);
      range.hi = bound(r->upper);
      p.range = std::move(range);
    }
    if (auto* rs = pc->rowSum()) {
      if (rs->kw->getText() != "rowsum") {
        diags_.error(loc(rs->kw), "unknown parameter constraint '" + rs->kw->getText() + "'; write 'rowsum X'");
      } else {
        p.rowsum = number(rs->number());
        p.rowsum_loc = loc(rs->kw);
      }
    }
    if (pc->expr() != nullptr) p.default_value = expr(pc->expr());
    return p;
  }

  std::string qual_name(P::QualNameContext* c) {
    std::string s;
    for (auto* id : c->IDENT()) {
      if (!s.empty()) s += '.';
      s += id->getText();
    }
    return s;
  }

  static std::string unescape(const std::string& quoted) {
    std::string out;
    for (std::size_t i = 1; i + 1 < quoted.size(); ++i) {
      char c = quoted[i];
      if (c == '\\' && i + 2 < quoted.size()) {
        c = quoted[++i];
        if (c == 'n') c = '\n';
        if (c == 't') c = '\t';
      }
      out += c;
    }
    return out;
  }

  std::vector<ast::Arg> args(const std::vector<P::ArgContext*>& cs) {
    std::vector<ast::Arg> out;
    for (P::ArgContext* a : cs) {
      ast::Arg arg;
      if (a->IDENT() != nullptr) arg.name = ident(a->IDENT());
      arg.value = expr(a->expr());
      out.push_back(std::move(arg));
    }
    return out;
  }

  ast::Call call(P::CallContext* c) {
    ast::Call call;
    call.name = qual_name(c->qualName());
    call.loc = loc(c);
    call.has_parens = c->children.size() > 1;
    call.args = args(c->arg());
    return call;
  }

  ast::Expr expr(P::ExprContext* c) {
    ast::Expr e;
    e.loc = loc(c);
    if (auto* n = dynamic_cast<P::NumberExprContext*>(c)) {
      e.kind = ast::Expr::Kind::Number;
      e.number = number(n->number());
    } else if (auto* s = dynamic_cast<P::StringExprContext*>(c)) {
      e.kind = ast::Expr::Kind::String;
      e.text = unescape(s->STRING()->getText());
    } else if (dynamic_cast<P::BoolExprContext*>(c) != nullptr) {
      e.kind = ast::Expr::Kind::Bool;
      e.text = c->getText();
    } else if (dynamic_cast<P::InfExprContext*>(c) != nullptr) {
      e.kind = ast::Expr::Kind::Inf;
    } else if (auto* ix = dynamic_cast<P::IndexExprContext*>(c)) {
      e.kind = ast::Expr::Kind::Index;
      e.text = ix->IDENT(0)->getText();
      e.index = ident(ix->IDENT(1));
    } else if (auto* ce = dynamic_cast<P::CallExprContext*>(c)) {
      e.kind = ast::Expr::Kind::Call;
      auto call = std::make_shared<ast::Call>();
      call->name = qual_name(ce->qualName());
      call->loc = loc(ce);
      call->has_parens = true;
      call->args = args(ce->arg());
      e.call = std::move(call);
    } else if (auto* ne = dynamic_cast<P::NameExprContext*>(c)) {
      e.kind = ast::Expr::Kind::Name;
      e.text = ne->IDENT()->getText();
    } else if (auto* le = dynamic_cast<P::ListExprContext*>(c)) {
      e.kind = ast::Expr::Kind::List;
      for (auto* x : le->expr()) e.items.push_back(expr(x));
    } else if (auto* se = dynamic_cast<P::SetExprContext*>(c)) {
      e.kind = ast::Expr::Kind::Set;
      for (auto* x : se->expr()) e.items.push_back(expr(x));
    }
    return e;
  }

  ast::Atom atom(P::AtomContext* c) {
    ast::Atom a;
    const auto ids = c->IDENT();
    a.pred = ident(ids.front());
    for (std::size_t i = 1; i < ids.size(); ++i) a.args.push_back(ident(ids[i]));
    return a;
  }

  // ---- formulas: depth-bounded ------------------------------------------------------
  bool too_deep(int depth, antlr4::ParserRuleContext* c) {
    if (depth <= kMaxFormulaDepth) return false;
    if (!depth_reported_) {
      diags_.error(loc(c), "formula nested too deeply (more than " + std::to_string(kMaxFormulaDepth) + " levels)");
      depth_reported_ = true;
    }
    return true;
  }

  static ast::Formula binary(ast::Formula::Kind k, const ast::Loc& at, ast::Formula lhs, ast::Formula rhs) {
    ast::Formula f;
    f.kind = k;
    f.loc = at;
    f.children.push_back(std::move(lhs));
    f.children.push_back(std::move(rhs));
    return f;
  }

  ast::Formula formula(P::FormulaContext* c, int depth) {
    const auto parts = c->implication();
    if (too_deep(depth + static_cast<int>(parts.size()) - 1, c)) return {};
    ast::Formula acc = implication(parts.front(), depth + static_cast<int>(parts.size()) - 1);
    for (std::size_t i = 1; i < parts.size(); ++i) {  // <=> folds to the left
      acc = binary(ast::Formula::Kind::Iff, loc(c), std::move(acc), implication(parts[i], depth + 1));
    }
    return acc;
  }

  ast::Formula implication(P::ImplicationContext* c, int depth) {
    const auto parts = c->disjunction();
    const int n = static_cast<int>(parts.size());
    if (too_deep(depth + n - 1, c)) return {};
    // => folds to the right: a => b => c is a => (b => c).
    ast::Formula acc = disjunction(parts.back(), depth + n - 1);
    for (int i = n - 2; i >= 0; --i) {
      const auto ui = static_cast<std::size_t>(i);
      acc = binary(ast::Formula::Kind::Implies, loc(parts[ui]), disjunction(parts[ui], depth + i + 1), std::move(acc));
    }
    return acc;
  }

  ast::Formula disjunction(P::DisjunctionContext* c, int depth) {
    const auto parts = c->conjunction();
    if (parts.size() == 1) return conjunction(parts.front(), depth);
    ast::Formula f;
    f.kind = ast::Formula::Kind::Or;
    f.loc = loc(c);
    for (auto* p : parts) f.children.push_back(conjunction(p, depth + 1));
    return f;
  }

  ast::Formula conjunction(P::ConjunctionContext* c, int depth) {
    const auto parts = c->unary();
    if (parts.size() == 1) return unary(parts.front(), depth);
    ast::Formula f;
    f.kind = ast::Formula::Kind::And;
    f.loc = loc(c);
    for (auto* p : parts) f.children.push_back(unary(p, depth + 1));
    return f;
  }

  ast::Formula unary(P::UnaryContext* c, int depth) {
    if (too_deep(depth, c)) return {};
    ast::Formula f;
    f.loc = loc(c);
    if (auto* n = dynamic_cast<P::NotFormulaContext*>(c)) {
      f.kind = ast::Formula::Kind::Not;
      f.children.push_back(unary(n->unary(), depth + 1));
    } else if (auto* e = dynamic_cast<P::ExistsFormulaContext*>(c)) {
      f.kind = ast::Formula::Kind::Exists;
      for (auto* id : e->IDENT()) f.vars.push_back(ident(id));
      f.children.push_back(formula(e->formula(), depth + 1));
    } else if (auto* a = dynamic_cast<P::AtomFormulaContext*>(c)) {
      f.kind = ast::Formula::Kind::Atom;
      f.atom = atom(a->atom());
    } else if (auto* p = dynamic_cast<P::ParenFormulaContext*>(c)) {
      return formula(p->formula(), depth + 1);
    }
    return f;
  }

  // ---- items ------------------------------------------------------------------------
  bool build_item(P::ItemContext* ic, ast::Item& item) {
    if (auto* c = dynamic_cast<P::DomainItemContext*>(ic)) {
      item.node = ast::DomainDecl{ident(c->IDENT())};
    } else if (auto* c = dynamic_cast<P::IncludeItemContext*>(ic)) {
      item.node = ast::IncludeDecl{unescape(c->STRING()->getText()), loc(c->STRING())};
    } else if (auto* c = dynamic_cast<P::TypeItemContext*>(ic)) {
      ast::TypeDecl t;
      const auto ids = c->IDENT();
      t.name = ident(ids.front());
      t.enumerated = c->children.size() > 3;
      for (std::size_t i = 1; i < ids.size(); ++i) t.constants.push_back(ident(ids[i]));
      item.node = std::move(t);
    } else if (auto* c = dynamic_cast<P::PredItemContext*>(ic)) {
      ast::PredDecl d;
      d.query = c->kind->getText() == "query";
      for (auto* sig : c->predSig()) {
        ast::PredSig ps;
        ps.name = ident(sig->IDENT());
        for (auto* pa : sig->predArg()) ps.args.push_back(ast::PredArg{ident(pa->IDENT()), pa->excl != nullptr});
        d.preds.push_back(std::move(ps));
      }
      item.node = std::move(d);
    } else if (auto* c = dynamic_cast<P::QuantityItemContext*>(ic)) {
      ast::QuantityDecl q;
      q.name = ident(c->IDENT());
      for (auto* u : c->unitDef()) q.units.push_back(ast::UnitDef{ident(u->IDENT()), number(u->number())});
      item.node = std::move(q);
    } else if (auto* c = dynamic_cast<P::ValueItemContext*>(ic)) {
      ast::ValueDecl v;
      for (auto* id : c->IDENT()) v.names.push_back(ident(id));
      item.node = std::move(v);
    } else if (auto* c = dynamic_cast<P::ExternItemContext*>(ic)) {
      ast::ExternDecl x;
      x.kind = ast::Ident{c->externKind()->getText(), loc(c->externKind())};
      x.name = qual_name(c->qualName());
      x.name_loc = loc(c->qualName());
      for (auto* ch : c->children) {
        if (auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(ch); t != nullptr && t->getText() == "(") {
          x.has_params = true;
        }
      }
      for (auto* pc : c->param()) x.params.push_back(param(pc));
      for (auto* tc : c->typeRef()) {
        if (tc == c->reads) x.reads = type_ref(tc);
        else x.result = type_ref(tc);
      }
      if (auto* m = dynamic_cast<P::MakesSpecContext*>(c->moveSpec())) {
        x.moves.kind = ast::MoveSpec::Kind::Makes;
        x.moves.loc = loc(m);
        for (auto* id : m->IDENT()) x.moves.moves.push_back(ident(id));
      } else if (auto* sv = dynamic_cast<P::ServesSpecContext*>(c->moveSpec())) {
        x.moves.kind = ast::MoveSpec::Kind::Serves;
        x.moves.loc = loc(sv);
        for (auto* id : sv->IDENT()) x.moves.moves.push_back(ident(id));
      }
      item.node = std::move(x);
    } else if (auto* c = dynamic_cast<P::ExternModelItemContext*>(ic)) {
      ast::ModelContractDecl d;
      for (auto* sc : c->modelSlot()) {
        ast::ModelSlot slot;
        slot.type = ident(sc->IDENT().front());
        slot.loc = loc(sc);
        slot.collection = sc->children.size() > 2;
        if (sc->index != nullptr) slot.index = ident(sc->index);
        slot.sampled = sc->vmode->getText() == "sampled";
        d.slots.push_back(std::move(slot));
      }
      item.node = std::move(d);
    } else if (auto* c = dynamic_cast<P::OutputItemContext*>(ic)) {
      item.node = ast::OutputDecl{call(c->call())};
    } else if (auto* c = dynamic_cast<P::RuleItemContext*>(ic)) {
      return build_rule(c, item);
    } else if (auto* c = dynamic_cast<P::ModelItemContext*>(ic)) {
      ast::ModelDecl m;
      m.name = ident(c->IDENT());
      for (auto* vc : c->modelVar()) {
        ast::ModelVar v;
        v.name = ident(vc->IDENT(0));
        v.loc = loc(vc);
        v.end_offset = vc->getStop()->getStopIndex() + 1;
        v.end_line = static_cast<int>(vc->getStop()->getLine());
        v.collection = vc->children.size() > 5;
        if (vc->index != nullptr) v.index = ident(vc->index);
        v.type = type_ref(vc->typeRef());
        v.sampled = vc->vmode->getText() == "sampled";
        m.vars.push_back(std::move(v));
      }
      item.node = std::move(m);
    } else if (auto* c = dynamic_cast<P::ExtractItemContext*>(ic)) {
      item.node = ast::ExtractDecl{atom(c->atom()), call(c->call())};
    } else if (auto* c = dynamic_cast<P::PriorItemContext*>(ic)) {
      ast::PriorDecl p;
      P::PriorFormContext* f = c->priorForm();
      p.quantified = f->getStart()->getText() == "for";
      for (auto* id : f->IDENT()) p.vars.push_back(ident(id));
      for (auto* cc : f->condition()) {
        ast::Condition cond;
        if (auto* pc = dynamic_cast<P::ProbConditionContext*>(cc)) {
          cond.is_prob = true;
          cond.fn = ident(pc->IDENT());
          cond.atom = atom(pc->atom());
          cond.op = pc->op->getText();
          cond.threshold = number(pc->number());
        } else if (auto* ac = dynamic_cast<P::AtomConditionContext*>(cc)) {
          cond.negated = ac->neg != nullptr;
          cond.atom = atom(ac->atom());
        }
        p.conditions.push_back(std::move(cond));
      }
      p.call = call(f->call());
      item.node = std::move(p);
    } else if (auto* c = dynamic_cast<P::LikelihoodItemContext*>(ic)) {
      item.node = ast::LikelihoodDecl{call(c->call())};
    } else if (auto* c = dynamic_cast<P::KernelPairItemContext*>(ic)) {
      ast::KernelDecl k;
      k.pair = true;
      k.name = ident(c->IDENT(0));
      k.reverse = ident(c->IDENT(1));
      if (c->kernelParams() != nullptr) k.params = kernel_params(c->kernelParams());
      for (auto* cc : c->call()) k.sources.push_back(call(cc));
      item.node = std::move(k);
    } else if (auto* c = dynamic_cast<P::KernelItemContext*>(ic)) {
      ast::KernelDecl k;
      k.name = ident(c->IDENT(0));
      if (c->IDENT().size() > 1) k.reverse = ident(c->IDENT(1));
      if (c->kernelParams() != nullptr) k.params = kernel_params(c->kernelParams());
      for (auto* cc : c->call()) k.sources.push_back(call(cc));
      item.node = std::move(k);
    } else if (auto* c = dynamic_cast<P::ScheduleItemContext*>(ic)) {
      ast::ScheduleDecl s;
      if (!c->scheduleEntry().empty()) {  // `schedule { a: 0.5, b: 0.5 }`: one row for all iterations
        ast::ScheduleRow row;
        row.loc = loc(c->scheduleEntry().front());
        const antlr4::Token* last = c->scheduleEntry().back()->getStop();
        row.end_offset = last->getStopIndex() + 1;
        row.end_line = static_cast<int>(last->getLine());
        for (auto* ec : c->scheduleEntry()) row.entries.push_back(ast::ScheduleEntry{ident(ec->IDENT()), number(ec->number())});
        s.rows.push_back(std::move(row));
      }
      for (auto* rc : c->scheduleRow()) {
        ast::ScheduleRow row;
        row.loc = loc(rc);
        row.end_offset = rc->getStop()->getStopIndex() + 1;
        row.end_line = static_cast<int>(rc->getStop()->getLine());
        if (rc->lo != nullptr) {
          row.has_range = true;
          row.lo = number(rc->lo);
          if (rc->hi->number() != nullptr) {
            row.hi_inf = false;
            row.hi = number(rc->hi->number());
          }
        }
        for (auto* ec : rc->scheduleEntry()) row.entries.push_back(ast::ScheduleEntry{ident(ec->IDENT()), number(ec->number())});
        s.rows.push_back(std::move(row));
      }
      item.node = std::move(s);
    } else {
      return false;
    }
    return true;
  }

  std::vector<ast::KernelParam> kernel_params(P::KernelParamsContext* c) {
    std::vector<ast::KernelParam> out;
    for (auto* k : c->kparam()) out.push_back(ast::KernelParam{ident(k->IDENT(0)), ident(k->IDENT(1))});
    return out;
  }

  bool build_rule(P::RuleItemContext* c, ast::Item& item) {
    ast::Rule r;
    P::RuleHeadContext* h = c->ruleHead();
    if (c->ruleName() != nullptr) r.label = ident(c->ruleName()->IDENT());
    r.head_loc = c->ruleName() != nullptr ? loc(c->ruleHead()->getStart()) : loc(c);
    r.hard = h->hard != nullptr;
    if (h->weightProb != nullptr) r.prob = number(h->number());
    if (h->weightRaw != nullptr) {
      if (h->weightRaw->getText() != "w") {
        diags_.error(loc(h->weightRaw), "unknown rule weight '" + h->weightRaw->getText() +
                                            "'; write 'hard', 'prob p:' or 'w x:'");
        return false;
      }
      r.weight = number(h->number());
    }
    r.source_text = source_text(c);
    if (c->ruleName() != nullptr) {  // without `@name`
      const std::string label = source_text(c->ruleName());
      std::size_t at = r.source_text.find(label);
      if (at == 0) r.source_text = r.source_text.substr(label.size());
      while (!r.source_text.empty() && std::isspace(static_cast<unsigned char>(r.source_text.front())))
        r.source_text.erase(r.source_text.begin());
    }
    if (auto* ex = dynamic_cast<P::ExactlyOneBodyContext*>(c->ruleBody())) {
      r.exactly_one = true;
      for (auto* a : ex->atom()) r.alternatives.push_back(atom(a));
    } else if (auto* fb = dynamic_cast<P::FormulaBodyContext*>(c->ruleBody())) {
      depth_reported_ = false;
      r.formula = formula(fb->formula(), 0);
      if (depth_reported_) return false;
    }
    item.node = std::move(r);
    return true;
  }

 private:
  const parse::ParsedFile& parsed_;
  diag::DiagEngine& diags_;
  bool depth_reported_ = false;
};

}  // namespace

ast::Module build_module(const parse::ParsedFile& parsed, const std::string& path, diag::DiagEngine& diags) {
  ast::Module m;
  m.file = parsed.file;
  m.path = path;
  if (parsed.tree == nullptr) return m;
  Builder b(parsed, diags);
  return b.run(path);
}

}  // namespace ksmc::compiler::build
