#include "compiler/lower/cnf.h"

#include <algorithm>
#include <map>
#include <memory>
#include <set>

namespace ksmc::compiler::lower {
namespace {

constexpr std::size_t kMaxClauses = 4096;

// Negation normal form: literals, conjunctions, disjunctions and positive existentials.
struct Nnf {
  enum class Kind { Lit, And, Or, Exists };
  Kind kind = Kind::Lit;
  CnfLiteral lit;
  std::vector<std::string> vars;  // Exists: renamed variables
  std::vector<Nnf> children;
  ast::Loc loc;
};

class Converter {
 public:
  explicit Converter(const std::vector<std::string>& constants)
      : constants_(constants.begin(), constants.end()) {}

  CnfResult run(const ast::Formula& f) {
    std::set<std::string> bound;
    collect_names(f, bound);
    std::map<std::string, std::string> subst;
    Nnf n = nnf(f, false, subst);
    CnfResult out;
    if (!error_.empty()) {
      out.error = error_;
      out.error_loc = error_loc_;
      return out;
    }
    out.clauses = cnf(n);
    if (!error_.empty()) {
      out.clauses.clear();
      out.error = error_;
      out.error_loc = error_loc_;
    }
    return out;
  }

 private:
  // Records every variable name and the names used free (outside a quantifier binding them).
  void collect_names(const ast::Formula& f, std::set<std::string>& bound) {
    if (f.kind == ast::Formula::Kind::Atom) {
      for (const auto& a : f.atom.args) {
        if (constants_.count(a.name)) continue;
        used_.insert(a.name);
        if (!bound.count(a.name)) free_.insert(a.name);
      }
    }
    std::set<std::string> inner = bound;
    for (const auto& v : f.vars) inner.insert(v.name);
    for (const auto& c : f.children) collect_names(c, inner);
  }

  // A name for a quantified variable: its own unless a free variable or an earlier
  // quantifier already uses it.
  std::string fresh(const std::string& base) {
    if (!quantified_.count(base) && !free_.count(base)) {
      quantified_.insert(base);
      return base;
    }
    for (int k = 2;; ++k) {
      std::string cand = base + std::to_string(k);
      if (!used_.count(cand) && !quantified_.count(cand)) {
        quantified_.insert(cand);
        used_.insert(cand);
        return cand;
      }
    }
  }
  Nnf nnf(const ast::Formula& f, bool neg, std::map<std::string, std::string>& subst) {
    using K = ast::Formula::Kind;
    switch (f.kind) {
      case K::Atom: {
        Nnf n;
        n.kind = Nnf::Kind::Lit;
        n.loc = f.loc;
        n.lit.atom = &f.atom;
        n.lit.negated = neg;
        for (const auto& a : f.atom.args) {
          auto it = subst.find(a.name);
          n.lit.args.push_back(it != subst.end() ? it->second : a.name);
        }
        return n;
      }
      case K::Not:
        return nnf(f.children.at(0), !neg, subst);
      case K::And:
      case K::Or: {
        Nnf n;
        n.loc = f.loc;
        const bool is_and = (f.kind == K::And) != neg;
        n.kind = is_and ? Nnf::Kind::And : Nnf::Kind::Or;
        for (const auto& c : f.children) n.children.push_back(nnf(c, neg, subst));
        return n;
      }
      case K::Implies: {  // a => b  ==  !a v b
        Nnf n;
        n.loc = f.loc;
        n.kind = neg ? Nnf::Kind::And : Nnf::Kind::Or;  // !(a => b) == a ^ !b
        n.children.push_back(nnf(f.children.at(0), !neg, subst));
        n.children.push_back(nnf(f.children.at(1), neg, subst));
        return n;
      }
      case K::Iff: {
        // a <=> b == (!a v b) ^ (a v !b);  !(a <=> b) == (a v b) ^ (!a v !b)
        const auto& a = f.children.at(0);
        const auto& b = f.children.at(1);
        Nnf n;
        n.loc = f.loc;
        n.kind = Nnf::Kind::And;
        for (int k = 0; k < 2; ++k) {
          Nnf d;
          d.loc = f.loc;
          d.kind = Nnf::Kind::Or;
          const bool na = neg ? (k == 1) : (k == 0);
          const bool nb = neg ? (k == 1) : (k == 1);
          d.children.push_back(nnf(a, na, subst));
          d.children.push_back(nnf(b, nb, subst));
          n.children.push_back(std::move(d));
        }
        return n;
      }
      case K::Exists: {
        std::map<std::string, std::string> inner = subst;
        std::vector<std::string> renamed;
        for (const auto& v : f.vars) {
          renamed.push_back(fresh(v.name));
          inner[v.name] = renamed.back();
        }
        Nnf body = nnf(f.children.at(0), neg, inner);
        if (neg) return body;  // !exists x: F == forall x: !F (x renamed apart)
        Nnf n;
        n.loc = f.loc;
        n.kind = Nnf::Kind::Exists;
        n.vars = std::move(renamed);
        n.children.push_back(std::move(body));
        return n;
      }
    }
    return {};
  }

  void fail(const ast::Loc& loc, std::string msg) {
    if (error_.empty()) {
      error_ = std::move(msg);
      error_loc_ = loc;
    }
  }

  std::vector<CnfClause> cnf(const Nnf& n) {
    if (!error_.empty()) return {};
    switch (n.kind) {
      case Nnf::Kind::Lit: {
        CnfClause c;
        c.literals.push_back(n.lit);
        return {c};
      }
      case Nnf::Kind::And: {
        std::vector<CnfClause> out;
        for (const auto& ch : n.children) {
          auto part = cnf(ch);
          out.insert(out.end(), part.begin(), part.end());
          if (out.size() > kMaxClauses) {
            fail(n.loc, "formula expands to more than " + std::to_string(kMaxClauses) + " clauses");
            return {};
          }
        }
        return out;
      }
      case Nnf::Kind::Or: {
        std::vector<CnfClause> acc{CnfClause{}};
        for (const auto& ch : n.children) {
          auto part = cnf(ch);
          if (!error_.empty()) return {};
          if (acc.size() * part.size() > kMaxClauses) {
            fail(n.loc, "formula expands to more than " + std::to_string(kMaxClauses) + " clauses");
            return {};
          }
          std::vector<CnfClause> next;
          for (const auto& a : acc) {
            for (const auto& b : part) {
              CnfClause c = a;
              c.literals.insert(c.literals.end(), b.literals.begin(), b.literals.end());
              for (const auto& e : b.existential)
                if (std::find(c.existential.begin(), c.existential.end(), e) == c.existential.end())
                  c.existential.push_back(e);
              next.push_back(std::move(c));
            }
          }
          acc = std::move(next);
        }
        return acc;
      }
      case Nnf::Kind::Exists: {
        auto body = cnf(n.children.at(0));
        for (const auto& v : n.vars) {
          int uses = 0;
          for (auto& c : body) {
            bool used = false;
            for (const auto& l : c.literals) used = used || std::count(l.args.begin(), l.args.end(), v) > 0;
            if (!used) continue;
            ++uses;
            c.existential.push_back(v);
          }
          if (uses > 1) {
            fail(n.loc, "'exists " + v +
                            "' ranges over a conjunction; write it so that every atom using '" + v +
                            "' is in one disjunction");
            return {};
          }
        }
        return body;
      }
    }
    return {};
  }

  std::set<std::string> constants_;
  std::set<std::string> used_;
  std::set<std::string> free_;
  std::set<std::string> quantified_;
  std::string error_;
  ast::Loc error_loc_;
};

}  // namespace

CnfResult to_cnf_impl(const ast::Formula& f, const std::vector<std::string>& constants) {
  return Converter(constants).run(f);
}

}  // namespace ksmc::compiler::lower
