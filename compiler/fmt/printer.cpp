#include "compiler/fmt/printer.h"

namespace ksmc::compiler::fmt {

std::string quote_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
  }
  return out + "\"";
}

std::string print_number(const ast::Number& n) { return n.unit.empty() ? n.text : n.text + " " + n.unit; }

std::string print_type(const ast::TypeRef& t) {
  if (t.is_set) return "set<" + t.name + ">";
  std::string s = t.name;
  for (int i = 0; i < t.list_depth; ++i) {
    const int n = i < static_cast<int>(t.dims.size()) ? t.dims[static_cast<std::size_t>(i)] : 0;
    s += n > 0 ? "[" + std::to_string(n) + "]" : std::string("[]");
  }
  return s;
}

std::string print_atom(const ast::Atom& a) {
  std::string s = a.pred.name + "(";
  for (std::size_t i = 0; i < a.args.size(); ++i) s += (i ? ", " : "") + a.args[i].name;
  return s + ")";
}

namespace {
std::string args(const std::vector<ast::Arg>& as) {
  std::string s;
  for (std::size_t i = 0; i < as.size(); ++i) {
    if (i) s += ", ";
    if (as[i].name) s += as[i].name->name + " = ";
    s += print_expr(as[i].value);
  }
  return s;
}

// Binding strength; a child binding no tighter than its parent gets parentheses.
int precedence(const ast::Formula& f) {
  switch (f.kind) {
    case ast::Formula::Kind::Exists: return 0;
    case ast::Formula::Kind::Iff: return 1;
    case ast::Formula::Kind::Implies: return 2;
    case ast::Formula::Kind::Or: return 3;
    case ast::Formula::Kind::And: return 4;
    case ast::Formula::Kind::Not: return 5;
    case ast::Formula::Kind::Atom: return 6;
  }
  return 0;
}

std::string child(const ast::Formula& c, int parent_prec) {
  const std::string s = print_formula(c);
  return precedence(c) <= parent_prec ? "(" + s + ")" : s;
}
}  // namespace

std::string print_expr(const ast::Expr& e) {
  switch (e.kind) {
    case ast::Expr::Kind::Number: return print_number(e.number);
    case ast::Expr::Kind::String: return quote_string(e.text);
    case ast::Expr::Kind::Bool: return e.text;
    case ast::Expr::Kind::Inf: return "inf";
    case ast::Expr::Kind::Name: return e.text;
    case ast::Expr::Kind::Index: return e.text + "[" + e.index.name + "]";
    case ast::Expr::Kind::Call: return print_call(*e.call);
    case ast::Expr::Kind::List:
    case ast::Expr::Kind::Set: {
      std::string s;
      for (std::size_t i = 0; i < e.items.size(); ++i) s += (i ? ", " : "") + print_expr(e.items[i]);
      return e.kind == ast::Expr::Kind::List ? "[" + s + "]" : "{" + s + "}";
    }
  }
  return "";
}

std::string print_call(const ast::Call& c) {
  return c.has_parens ? c.name + "(" + args(c.args) + ")" : c.name;
}

std::string print_formula(const ast::Formula& f) {
  const int p = precedence(f);
  switch (f.kind) {
    case ast::Formula::Kind::Atom: return print_atom(f.atom);
    case ast::Formula::Kind::Not: return "!" + child(f.children[0], 4);  // binary and exists children need ( )
    case ast::Formula::Kind::Exists: {
      std::string s = "exists ";
      for (std::size_t i = 0; i < f.vars.size(); ++i) s += (i ? ", " : "") + f.vars[i].name;
      return s + ": " + print_formula(f.children[0]);
    }
    default: {
      const char* op = f.kind == ast::Formula::Kind::And ? " ^ " : f.kind == ast::Formula::Kind::Or ? " v "
                       : f.kind == ast::Formula::Kind::Implies                                    ? " => "
                                                                                                  : " <=> ";
      std::string s;
      for (std::size_t i = 0; i < f.children.size(); ++i) s += (i ? op : "") + child(f.children[i], p);
      return s;
    }
  }
}

}  // namespace ksmc::compiler::fmt
