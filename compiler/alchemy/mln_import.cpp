#include "compiler/alchemy/mln_import.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

#include "compiler/check/pass.h"

namespace ksmc::compiler::alchemy {
namespace {

// Words of the ksm language that cannot name a predicate, type, constant or variable.
const std::set<std::string> kKeywords{
    "domain", "include", "type",   "evidence", "query",    "quantity", "value",    "extern", "hard",
    "prob",   "exactly", "one",    "of",       "exists",   "model",    "extract",  "prior",  "likelihood",
    "kernel", "pair",    "reverse", "schedule", "for",     "where",    "and",      "set",    "inf",
    "true",   "false",   "fixed",  "sampled",  "v"};

struct Token {
  enum Kind { Ident, Number, String, Sym, End } kind = End;
  std::string text;
  int col = 0;
};

// Blanks out comments, keeping line and column positions.
std::string strip_comments(std::string text) {
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i) {}
      continue;
    }
    if (text[i] == '/' && text[i + 1] == '/') {
      for (; i < text.size() && text[i] != '\n'; ++i) text[i] = ' ';
    } else if (text[i] == '/' && text[i + 1] == '*') {
      for (; i < text.size() && !(text[i] == '*' && i + 1 < text.size() && text[i + 1] == '/'); ++i)
        if (text[i] != '\n') text[i] = ' ';
      if (i < text.size()) text[i] = ' ';
      if (i + 1 < text.size()) text[i + 1] = ' ';
    }
  }
  return text;
}

struct Error {
  int col;
  std::string message;
};

std::vector<Token> tokenize(const std::string& line) {
  std::vector<Token> out;
  std::size_t i = 0;
  auto digit = [&](std::size_t k) { return k < line.size() && std::isdigit(static_cast<unsigned char>(line[k])); };
  while (i < line.size()) {
    const char c = line[i];
    const int col = static_cast<int>(i) + 1;
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < line.size() && (std::isalnum(static_cast<unsigned char>(line[j])) || line[j] == '_')) ++j;
      out.push_back({Token::Ident, line.substr(i, j - i), col});
      i = j;
    } else if (digit(i) || ((c == '-' || c == '+') && (digit(i + 1) || (line[i + 1] == '.' && digit(i + 2)))) ||
               (c == '.' && digit(i + 1))) {
      std::size_t j = i + 1;
      while (digit(j) || (j < line.size() && line[j] == '.' && digit(j + 1))) ++j;
      if (j < line.size() && (line[j] == 'e' || line[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < line.size() && (line[k] == '-' || line[k] == '+')) ++k;
        if (digit(k)) {
          j = k;
          while (digit(j)) ++j;
        }
      }
      out.push_back({Token::Number, line.substr(i, j - i), col});
      i = j;
    } else if (c == '"') {
      const auto e = line.find('"', i + 1);
      const std::size_t j = e == std::string::npos ? line.size() : e + 1;
      out.push_back({Token::String, line.substr(i, j - i), col});
      i = j;
    } else if (line.compare(i, 3, "<=>") == 0) {
      out.push_back({Token::Sym, "<=>", col});
      i += 3;
    } else if (line.compare(i, 2, "=>") == 0) {
      out.push_back({Token::Sym, "=>", col});
      i += 2;
    } else {
      out.push_back({Token::Sym, std::string(1, c), col});
      ++i;
    }
  }
  out.push_back({Token::End, "", static_cast<int>(line.size()) + 1});
  return out;
}

struct Node {
  enum Kind { Atom, Not, And, Or, Imp, Iff, Exist } kind = Atom;
  std::string pred;
  std::vector<std::string> args;  // atom arguments, or the exists variables
  std::unique_ptr<Node> a, b;
};

// Whether variable v occurs free in n (an inner EXIST over v hides it).
bool occurs(const Node& n, const std::string& v) {
  if (n.kind == Node::Atom) return std::find(n.args.begin(), n.args.end(), v) != n.args.end();
  if (n.kind == Node::Exist && std::find(n.args.begin(), n.args.end(), v) != n.args.end()) return false;
  return (n.a && occurs(*n.a, v)) || (n.b && occurs(*n.b, v));
}

struct PredInfo {
  std::vector<std::string> types;
  std::vector<bool> exclusive;
};

class Translator {
 public:
  Translator(const std::string& path, bool per_formula) : path_(path), per_formula_(per_formula) {}

  ImportResult run(const std::string& text, const std::vector<std::string>& queries) {
    std::istringstream in(strip_comments(text));
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
      ++line_no;
      line_no_ = line_no;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      try {
        statement(line);
      } catch (const Error& e) {
        errors_.push_back(path_ + ":" + std::to_string(line_no) + ":" + std::to_string(e.col) + ": error: " + e.message);
      }
    }
    std::set<std::string> query_set;
    for (const auto& q : queries) {
      if (!preds_.count(q))
        errors_.push_back(path_ + ": error: --query: '" + q + "' is not a predicate declared in the file");
      query_set.insert(q);
    }
    ImportResult r;
    r.errors = errors_;
    if (!errors_.empty()) return r;
    std::ostringstream out;
    out << "// Imported from " << std::filesystem::path(path_).filename().string()
        << " by `ksmc import-mln` (Alchemy syntax; "
        << (per_formula_ ? "per-formula weights: a formula of several CNF clauses puts its weight on an auxiliary atom holds_k equivalent to it"
                         : "weights split over CNF clauses as in Alchemy")
        << ").\n";
    out << "domain " << domain_name() << ";\n\n";
    for (const auto& t : type_order_) {
      out << "type " << t;
      if (const auto it = enumerated_.find(t); it != enumerated_.end()) {
        out << " = {";
        for (std::size_t k = 0; k < it->second.size(); ++k) out << (k ? ", " : "") << it->second[k];
        out << "}";
      }
      out << ";\n";
    }
    out << "\n";
    for (const auto& name : pred_order_) {
      const auto& p = preds_.at(name);
      const bool query = queries.empty() || query_set.count(name) > 0;
      out << (query ? "query " : "evidence ") << name << "(";
      bool dropped = false;
      for (std::size_t k = 0; k < p.types.size(); ++k) {
        out << (k ? ", " : "") << p.types[k] << (p.exclusive[k] && query ? "!" : "");
        dropped = dropped || (p.exclusive[k] && !query);
      }
      out << ");" << (dropped ? "  // '!' dropped: exclusive arguments constrain query predicates only" : "") << "\n";
    }
    out << aux_decls_.str() << "\n" << rules_.str();
    r.ksm = out.str();
    return r;
  }

 private:
  [[noreturn]] static void fail(const Token& t, const std::string& message) { throw Error{t.col, message}; }

  std::string domain_name() const {
    std::string stem = std::filesystem::path(path_).stem().string(), out;
    for (char c : stem) out.push_back(std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0])) || kKeywords.count(out)) out = "mln_" + out;
    return out;
  }

  void check_name(const Token& t, const char* what) const {
    if (kKeywords.count(t.text)) fail(t, std::string(what) + " '" + t.text + "' is a word of the ksm language; rename it");
  }

  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_++]; }
  bool sym(const char* s) const { return peek().kind == Token::Sym && peek().text == s; }
  void expect(const char* s) {
    if (!sym(s)) fail(peek(), std::string("expected '") + s + "', found " + describe(peek()));
    ++pos_;
  }
  static std::string describe(const Token& t) {
    return t.kind == Token::End ? "the end of the line" : "'" + t.text + "'";
  }

  void statement(const std::string& line) {
    toks_ = tokenize(line);
    pos_ = 0;
    var_types_.clear();
    if (peek().kind == Token::End) return;
    if (sym("#")) fail(peek(), "'#include' and other directives are not supported; merge the files");
    // type declaration: name = { ... }
    if (peek().kind == Token::Ident && toks_[1].kind == Token::Sym && toks_[1].text == "=") return type_decl();
    // predicate declaration: first bare atom of an undeclared predicate
    if (peek().kind == Token::Ident && toks_[1].kind == Token::Sym && toks_[1].text == "(" && !preds_.count(peek().text) &&
        is_bare_atom())
      return pred_decl();
    if (peek().kind == Token::Ident && toks_[1].kind == Token::Ident && toks_[2].kind == Token::Sym && toks_[2].text == "(")
      fail(toks_[1], "function declarations ('" + peek().text + " " + toks_[1].text + "(...)') are not supported");
    formula_statement();
  }

  bool is_bare_atom() const {
    std::size_t k = 2;
    while (k < toks_.size() && !(toks_[k].kind == Token::Sym && toks_[k].text == ")")) ++k;
    return k + 2 == toks_.size();  // ")" then End
  }

  void type_decl() {
    const Token name = next();
    check_name(name, "type");
    ++pos_;  // '='
    expect("{");
    std::vector<std::string> constants;
    while (true) {
      const Token& t = next();
      if (t.kind == Token::Number) fail(t, "integer or numeric types ('" + name.text + " = {" + t.text + ", ...}') are not supported");
      if (t.kind == Token::String) fail(t, "string constants (" + t.text + ") are not supported");
      if (t.kind != Token::Ident) fail(t, "expected a constant name, found " + describe(t));
      check_name(t, "constant");
      if (!std::isupper(static_cast<unsigned char>(t.text[0])))
        fail(t, "constant '" + t.text + "' must be capitalised (lowercase names are variables)");
      constants.push_back(t.text);
      if (sym(",")) { ++pos_; continue; }
      expect("}");
      break;
    }
    if (peek().kind != Token::End) fail(peek(), "unexpected " + describe(peek()) + " after the type declaration");
    if (enumerated_.count(name.text)) fail(name, "type '" + name.text + "' is declared twice");
    use_type(name.text);
    enumerated_[name.text] = constants;
    for (const auto& c : constants) constant_type_[c] = name.text;
  }

  void use_type(const std::string& t) {
    if (std::find(type_order_.begin(), type_order_.end(), t) == type_order_.end()) type_order_.push_back(t);
  }

  void pred_decl() {
    const Token name = next();
    check_name(name, "predicate");
    expect("(");
    PredInfo p;
    while (true) {
      const Token& t = next();
      if (t.kind != Token::Ident) fail(t, "expected a type name in the declaration of '" + name.text + "', found " + describe(t));
      check_name(t, "type");
      p.types.push_back(t.text);
      use_type(t.text);
      bool excl = false;
      if (sym("!")) { ++pos_; excl = true; }
      p.exclusive.push_back(excl);
      if (sym(",")) { ++pos_; continue; }
      expect(")");
      break;
    }
    preds_[name.text] = p;
    pred_order_.push_back(name.text);
  }

  // An Alchemy weight as the ksm grammar writes a number ('-'? digits ('.' digits)? exponent?):
  // "+2" -> "2", ".07" -> "0.07", "-.5" -> "-0.5"; anything else (two points: "1.2.3") is an error
  // here rather than a .ksm the front end refuses.
  std::string ksm_number(const Token& t) const {
    std::string x = t.text;
    std::string sign;
    if (!x.empty() && (x[0] == '+' || x[0] == '-')) {
      if (x[0] == '-') sign = "-";
      x.erase(0, 1);
    }
    if (!x.empty() && x[0] == '.') x.insert(0, "0");
    const auto mantissa = x.substr(0, x.find_first_of("eE"));
    if (std::count(mantissa.begin(), mantissa.end(), '.') > 1) fail(t, "weight '" + t.text + "' is not a number");
    return sign + x;
  }

  void formula_statement() {
    const Token start = peek();
    std::string weight;
    if (peek().kind == Token::Number) weight = ksm_number(next());
    auto f = iff();
    bool hard = false;
    if (sym(".")) {
      hard = true;
      if (!weight.empty()) fail(peek(), "a hard formula (ending in '.') cannot have a weight (" + weight + ")");
      ++pos_;
    }
    if (sym("=")) fail(peek(), "equality ('=') is not supported");
    if (peek().kind != Token::End) fail(peek(), "unexpected " + describe(peek()) + " after the formula");
    if (!hard && per_formula_ && !one_clause(*f, true)) {
      per_formula_rule(*f, weight.empty() ? "0" : weight, start);
      return;
    }
    // Alchemy allows a formula twice (two factors, i.e. their weights add); ksm names an
    // unnamed rule from its formula, so the repeat gets a name of its own.
    const std::string text = print(*f, true);
    if (!formulas_.insert(text).second) rules_ << "@mln_line" << line_no_ << " ";
    if (hard) rules_ << "hard ";
    else if (weight.empty()) rules_ << "w 0: ";  // Alchemy: weight to be learned
    else rules_ << "w " << weight << ": ";
    rules_ << text << ".";
    if (!hard && weight.empty()) rules_ << "  // no weight in the .mln: to be learned";
    rules_ << "\n";
  }

  // True when the formula (under `positive` polarity) converts to a single CNF clause.
  static bool one_clause(const Node& n, bool positive) {
    switch (n.kind) {
      case Node::Atom: return true;
      case Node::Not: return one_clause(*n.a, !positive);
      case Node::And: return !positive && one_clause(*n.a, false) && one_clause(*n.b, false);
      case Node::Or: return positive && one_clause(*n.a, true) && one_clause(*n.b, true);
      case Node::Imp: return positive && one_clause(*n.a, false) && one_clause(*n.b, true);
      case Node::Exist: return positive && one_clause(*n.a, true);
      case Node::Iff: return false;
    }
    return false;
  }

  // The free variables of `n` in order of appearance, with their types (from the
  // argument positions they fill); `EXIST` is refused.
  void free_variables(const Node& n, const Token& at, std::vector<std::pair<std::string, std::string>>& out) const {
    if (n.kind == Node::Exist)
      fail(at, "--per-formula: EXIST in a formula of several CNF clauses is not supported");
    if (n.kind != Node::Atom) {
      if (n.a) free_variables(*n.a, at, out);
      if (n.b) free_variables(*n.b, at, out);
      return;
    }
    const auto& types = preds_.at(n.pred).types;
    for (std::size_t k = 0; k < n.args.size(); ++k) {
      if (std::isupper(static_cast<unsigned char>(n.args[k][0]))) continue;
      bool seen = false;
      for (const auto& v : out) seen = seen || v.first == n.args[k];
      if (!seen) out.emplace_back(n.args[k], types[k]);
    }
  }

  // Per-formula weight through an auxiliary query atom equivalent to the formula:
  //   query holds_k(types);  hard holds_k(vars) <=> (F).  w W: holds_k(vars).
  void per_formula_rule(const Node& f, const std::string& weight, const Token& at) {
    std::vector<std::pair<std::string, std::string>> vars;
    free_variables(f, at, vars);
    if (vars.empty()) fail(at, "--per-formula: a formula without variables needs no auxiliary atom; write it as one clause");
    std::string name;
    do name = "holds_" + std::to_string(++aux_count_); while (preds_.count(name));
    std::string decl, args;
    for (std::size_t k = 0; k < vars.size(); ++k) {
      decl += (k ? ", " : "") + vars[k].second;
      args += (k ? ", " : "") + vars[k].first;
    }
    aux_decls_ << "query " << name << "(" << decl << ");  // auxiliary: " << name << " <=> the formula\n";
    rules_ << "hard " << name << "(" << args << ") <=> (" << print(f, true) << ").\n";
    rules_ << "w " << weight << ": " << name << "(" << args << ").\n";
  }

  std::unique_ptr<Node> binary(Node::Kind k, std::unique_ptr<Node> a, std::unique_ptr<Node> b) {
    auto n = std::make_unique<Node>();
    n->kind = k;
    n->a = std::move(a);
    n->b = std::move(b);
    return n;
  }
  std::unique_ptr<Node> iff() {
    auto l = imp();
    while (sym("<=>")) { ++pos_; l = binary(Node::Iff, std::move(l), imp()); }
    return l;
  }
  std::unique_ptr<Node> imp() {
    auto l = disj();
    if (sym("=>")) { ++pos_; return binary(Node::Imp, std::move(l), imp()); }
    return l;
  }
  std::unique_ptr<Node> disj() {
    auto l = conj();
    while (peek().kind == Token::Ident && peek().text == "v") { ++pos_; l = binary(Node::Or, std::move(l), conj()); }
    return l;
  }
  std::unique_ptr<Node> conj() {
    auto l = unary();
    while (sym("^")) { ++pos_; l = binary(Node::And, std::move(l), unary()); }
    return l;
  }
  std::unique_ptr<Node> unary() {
    const Token& t = peek();
    if (sym("!")) {
      ++pos_;
      auto n = std::make_unique<Node>();
      n->kind = Node::Not;
      n->a = unary();
      return n;
    }
    if (sym("(")) {
      ++pos_;
      auto f = iff();
      expect(")");
      return f;
    }
    if (sym("+") || sym("*")) fail(t, "the '" + t.text + "' operator (per-constant weights / sign choices) is not supported");
    if (t.kind == Token::Ident && t.text == "FORALL")
      fail(t, "FORALL is not supported (free variables are universally quantified already)");
    if (t.kind == Token::Ident && t.text == "EXIST") {
      ++pos_;
      auto n = std::make_unique<Node>();
      n->kind = Node::Exist;
      std::vector<Token> vars;
      while (true) {
        const Token& v = next();
        if (v.kind != Token::Ident || !std::islower(static_cast<unsigned char>(v.text[0])))
          fail(v, "expected a lowercase variable after EXIST, found " + describe(v));
        check_name(v, "variable");
        n->args.push_back(v.text);
        vars.push_back(v);
        if (sym(",")) { ++pos_; continue; }
        break;
      }
      n->a = iff();
      for (const Token& v : vars)
        if (!occurs(*n->a, v.text)) fail(v, "EXIST variable '" + v.text + "' does not occur in the formula it quantifies");
      return n;
    }
    if (t.kind != Token::Ident) fail(t, "expected an atom, '!', '(' or EXIST, found " + describe(t));
    if (toks_[pos_ + 1].kind == Token::Sym && toks_[pos_ + 1].text == "=")
      fail(toks_[pos_ + 1], "equality ('" + t.text + " = ...') is not supported");
    return atom();
  }
  std::unique_ptr<Node> atom() {
    const Token name = next();
    const auto it = preds_.find(name.text);
    if (it == preds_.end()) {
      const std::string near = check::suggest(name.text, pred_order_);
      fail(name, "predicate '" + name.text + "' is not declared" +
                     (near.empty() ? " (declare it as " + name.text + "(type, ...) first)" : " (did you mean '" + near + "'?)"));
    }
    if (!sym("(")) fail(peek(), "expected '(' after '" + name.text + "', found " + describe(peek()));
    ++pos_;
    auto n = std::make_unique<Node>();
    n->pred = name.text;
    while (true) {
      const Token& a = next();
      if (a.kind == Token::Number) fail(a, "numeric constants (" + a.text + ") are not supported");
      if (a.kind == Token::String) fail(a, "string constants (" + a.text + ") are not supported");
      if (a.kind == Token::Sym && (a.text == "+" || a.text == "*"))
        fail(a, "the '" + a.text + "' operator (per-constant weights / sign choices) is not supported");
      if (a.kind != Token::Ident) fail(a, "expected a variable or constant, found " + describe(a));
      check_name(a, std::isupper(static_cast<unsigned char>(a.text[0])) ? "constant" : "variable");
      const std::size_t k = n->args.size();
      if (k < it->second.types.size() && std::isupper(static_cast<unsigned char>(a.text[0]))) {
        const std::string& type = it->second.types[k];
        const auto en = enumerated_.find(type);
        if (en == enumerated_.end() || std::find(en->second.begin(), en->second.end(), a.text) == en->second.end())
          fail(a, "constant '" + a.text + "' must be declared in its type (" + type + " = {" + a.text +
                      ", ...}): ksm rules only name declared constants");
      }
      if (k < it->second.types.size() && std::islower(static_cast<unsigned char>(a.text[0]))) {
        // One type per variable in a formula (ksm rules are typed; Alchemy refuses it too).
        const std::string& type = it->second.types[k];
        const auto [seen, fresh] = var_types_.emplace(a.text, std::make_pair(type, a.col));
        if (!fresh && seen->second.first != type)
          fail(a, "variable '" + a.text + "' is of type '" + type + "' here but of type '" + seen->second.first +
                      "' at column " + std::to_string(seen->second.second));
      }
      n->args.push_back(a.text);
      if (sym(",")) { ++pos_; continue; }
      expect(")");
      break;
    }
    if (n->args.size() != it->second.types.size())
      fail(name, "'" + name.text + "' takes " + std::to_string(it->second.types.size()) + " arguments, got " +
                     std::to_string(n->args.size()));
    return n;
  }

  static std::string print(const Node& n, bool top = false) {
    switch (n.kind) {
      case Node::Atom: {
        std::string s = n.pred + "(";
        for (std::size_t k = 0; k < n.args.size(); ++k) s += (k ? ", " : "") + n.args[k];
        return s + ")";
      }
      case Node::Not:
        return "!" + wrap(*n.a);
      case Node::Exist: {
        std::string s = "exists ";
        for (std::size_t k = 0; k < n.args.size(); ++k) s += (k ? ", " : "") + n.args[k];
        s += ": " + print(*n.a, true);
        return top ? s : "(" + s + ")";
      }
      default: {
        const char* op = n.kind == Node::And ? " ^ " : n.kind == Node::Or ? " v " : n.kind == Node::Imp ? " => " : " <=> ";
        // a left-nested chain of ^ or v needs no parentheses
        const bool chain = (n.kind == Node::And || n.kind == Node::Or) && n.a->kind == n.kind;
        const std::string s = (chain ? print(*n.a, true) : wrap(*n.a)) + op + wrap(*n.b);
        return top ? s : "(" + s + ")";
      }
    }
  }
  static std::string wrap(const Node& n) { return print(n, n.kind == Node::Atom || n.kind == Node::Not); }

  std::string path_;
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  std::map<std::string, PredInfo> preds_;
  std::vector<std::string> pred_order_, type_order_;
  std::map<std::string, std::vector<std::string>> enumerated_;
  std::map<std::string, std::string> constant_type_;
  std::map<std::string, std::pair<std::string, int>> var_types_;  // the current formula's: type, first column
  std::ostringstream rules_, aux_decls_;
  std::vector<std::string> errors_;
  bool per_formula_ = false;
  int aux_count_ = 0;
  int line_no_ = 0;
  std::set<std::string> formulas_;  // the rules written so far, as printed
};

}  // namespace

ImportResult import_mln(const std::string& text, const std::string& path, const std::vector<std::string>& queries,
                        bool per_formula) {
  return Translator(path, per_formula).run(text, queries);
}

int run_import(const std::vector<std::string>& files, const std::vector<std::string>& queries,
               const std::string& out_path, std::ostream& out, std::ostream& err, bool per_formula) {
  if (files.size() != 1) {
    err << "ksmc import-mln: give one FILE.mln\n";
    return 2;
  }
  std::ifstream in(files.front(), std::ios::binary);
  if (!in) {
    err << files.front() << ": error: cannot read the file\n";
    return 1;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const ImportResult r = import_mln(buffer.str(), files.front(), queries, per_formula);
  for (const auto& e : r.errors) err << e << "\n";
  if (!r.errors.empty()) {
    err << "ksmc import-mln: " << r.errors.size() << (r.errors.size() == 1 ? " error" : " errors") << "\n";
    return 1;
  }
  if (out_path.empty()) {
    out << r.ksm;
    return 0;
  }
  std::ofstream file(out_path, std::ios::binary);
  file << r.ksm;
  if (!file) {
    err << "ksmc import-mln: cannot write '" << out_path << "'\n";
    return 1;
  }
  return 0;
}

}  // namespace ksmc::compiler::alchemy
