#include "compiler/emit/emit_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "compiler/check/rule_names.h"
#include "compiler/fmt/printer.h"
#include "compiler/lower/dump_ir.h"

namespace ksmc::compiler::emit {
namespace {

using lower::one_line;

// A name of the domain language as a C++ identifier: a C++ keyword gets a trailing
// underscore (`seg.short` -> `seg::short_`; stdlib/<kit>/blocks.h declares it so).
std::string block_identifier(const std::string& name) {
  static const std::set<std::string> keywords = {
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
      "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
      "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
      "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
      "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
      "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
      "requires", "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct",
      "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename",
      "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};
  return keywords.count(name) ? name + "_" : name;
}

// `geom.room_like` -> `blk::geom::room_like`.
std::string block_name(const std::string& qualified) {
  std::string s = "blk::";
  std::string part;
  for (char ch : qualified) {
    if (ch == '.') {
      s += block_identifier(part) + "::";
      part.clear();
    } else {
      part.push_back(ch);
    }
  }
  return s + block_identifier(part);
}

// A C++ double literal that reads back to exactly `v`.
std::string double_literal(double v) {
  if (std::isinf(v)) return v > 0 ? "std::numeric_limits<double>::infinity()" : "-std::numeric_limits<double>::infinity()";
  std::string s = lower::format_weight(v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

class ModelEmitter {
 public:
  ModelEmitter(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources,
               std::string kit)
      : program_(program), symbols_(symbols), sources_(sources), kit_(std::move(kit)),
        ns_(cpp_identifier(symbols.domain)) {}

  ModelOutput run() {
    ModelOutput out;
    out.header = {ns_ + "_model.h", header()};
    out.source = {ns_ + "_model.cpp", source()};
    out.main = {ns_ + "_main.cpp", main_file()};
    return out;
  }

 private:
  // Variables of the item being emitted: name -> index into `c` (entity constants), and
  // the kernel parameters (their model-variable arguments are not passed).
  struct Frame {
    std::map<std::string, int> vars;
    std::set<std::string> kernel_params;
    bool per_binding = false;  // `s` is in scope
  };

  const std::string& main_path() const { return program_.modules.front().path; }

  // Item offsets count code points (ANTLR decodes UTF-8); the source text is bytes.
  static std::size_t byte_offset(const std::string& text, std::size_t code_points) {
    std::size_t seen = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;  // continuation byte
      if (seen++ == code_points) return i;
    }
    return text.size();
  }

  std::string item_text(const ast::Item& item) const {
    const std::string& text = sources_.text(item.loc.file);
    const std::size_t begin = byte_offset(text, item.loc.offset);
    const std::size_t end = byte_offset(text, item.end_offset);
    if (begin >= text.size() || end <= begin) return {};
    return one_line(std::string_view(text).substr(begin, end - begin));
  }

  double unit_scale(const std::string& unit) const {
    if (unit.empty()) return 1.0;
    auto it = symbols_.units.find(unit);
    return it == symbols_.units.end() ? 1.0 : it->second.scale;
  }

  static std::string pred(const std::string& name) { return "kPred_" + cpp_identifier(name); }

  const ast::ModelVar* model_var(const std::string& name) const {
    auto it = symbols_.model_vars.find(name);
    return it == symbols_.model_vars.end() ? nullptr : it->second.decl;
  }

  // An argument value for parameter type `t` (nullptr for nested list items).
  std::string value(const ast::Expr& e, const ast::TypeRef* t, const Frame& f) const {
    using K = ast::Expr::Kind;
    const bool is_int = t != nullptr && t->name == "int" && t->list_depth == 0 && !t->is_set;
    switch (e.kind) {
      case K::Number: {
        const double v = e.number.value * unit_scale(e.number.unit);
        if (is_int) return lower::format_weight(v);
        return double_literal(v);
      }
      case K::String: return cpp_string(e.text);
      case K::Bool: return e.text == "true" ? "true" : "false";
      case K::Inf: return double_literal(std::numeric_limits<double>::infinity());
      case K::Name: {
        if (auto v = f.vars.find(e.text); v != f.vars.end()) return "c[" + std::to_string(v->second) + "]";
        if (symbols_.predicate(e.text) != nullptr) return pred(e.text);
        if (const ast::ModelVar* mv = model_var(e.text)) {
          return mv->collection ? "s." + mv->type.name + "s()" : "s." + mv->type.name + "()";
        }
        return cpp_identifier(e.text);
      }
      case K::Index: {
        const ast::ModelVar* mv = model_var(e.text);
        const std::string type = mv != nullptr ? mv->type.name : e.text;
        auto v = f.vars.find(e.index.name);
        return "s." + type + "(c[" + std::to_string(v != f.vars.end() ? v->second : 0) + "])";
      }
      case K::Call: return call(*e.call, f, true);
      case K::List:
      case K::Set: {
        std::string s = "{";
        for (std::size_t i = 0; i < e.items.size(); ++i) s += (i ? ", " : "") + value(e.items[i], nullptr, f);
        return s + "}";
      }
    }
    return "{}";
  }

  // The arguments of `c` matched to the declared parameters, defaults filled in.
  std::vector<const ast::Expr*> bind(const ast::Call& c, const ast::ExternDecl& x) const {
    std::vector<const ast::Expr*> out(x.params.size(), nullptr);
    std::size_t positional = 0;
    for (const ast::Arg& a : c.args) {
      if (!a.name) {
        if (positional < out.size()) out[positional++] = &a.value;
        continue;
      }
      for (std::size_t i = 0; i < x.params.size(); ++i)
        if (x.params[i].name.name == a.name->name) out[i] = &a.value;
    }
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out[i] == nullptr && x.params[i].default_value) out[i] = &*x.params[i].default_value;
    return out;
  }

  // A per-binding block (extractor, function, term prior) takes the scene first.
  std::string call(const ast::Call& c, const Frame& f, bool per_binding) const {
    auto it = symbols_.externs.find(c.name);
    if (it == symbols_.externs.end()) return block_name(c.name) + "()";
    const ast::ExternDecl& x = *it->second.decl;
    const std::vector<const ast::Expr*> args = bind(c, x);
    std::string s = block_name(c.name) + "(";
    std::string sep;
    if (per_binding) {
      s += "s";
      sep = ", ";
    }
    std::string pending;  // dropped arguments, as comments before the next one
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (args[i] == nullptr) continue;
      const ast::Expr& e = *args[i];
      if (e.kind == ast::Expr::Kind::Index && f.kernel_params.count(e.index.name) != 0) {
        pending += "/* " + fmt::print_expr(e) + " */ ";
        continue;
      }
      s += sep + pending + value(e, &x.params[i].type, f);
      pending.clear();
      sep = ", ";
    }
    if (!pending.empty()) s += sep + pending.substr(0, pending.size() - 1);
    return s + ")";
  }

  bool is_term_prior(const std::string& name) const {
    auto it = symbols_.externs.find(name);
    return it != symbols_.externs.end() && it->second.decl->result.has_value();
  }

  std::string header() const {
    std::ostringstream o;
    o << "// Generated by ksmc from " << main_path() << ": the binding of domain `" << symbols_.domain
      << "` to the stdlib kit `" << kit_ << "`.\n"
      << "// Do not edit: change the domain file and run `ksmc emit` again.\n"
      << "#pragma once\n\n"
      << "#include \"stdlib/" << kit_ << "/blocks.h\"\n\n"
      << "namespace ksmc_generated::" << ns_ << " {\n\n"
      << "// Every model, extract, prior, likelihood, output, kernel and schedule item of the domain\n"
      << "// file, bound to the kit's blocks (docs/binding.md).\n"
      << "const ksmc::stdlib::" << cpp_identifier(kit_) << "::blocks::Binding& binding();\n\n"
      << "}  // namespace ksmc_generated::" << ns_ << "\n";
    return o.str();
  }

  // The constant type of the kit: the element type of the model's run-time collections.
  std::string constant_type() const {
    for (const ast::Item& item : program_.modules.front().items) {
      const auto* m = std::get_if<ast::ModelDecl>(&item.node);
      if (m == nullptr) continue;
      for (const ast::ModelVar& v : m->vars) {
        auto it = symbols_.model_vars.find(v.name.name);
        if (it != symbols_.model_vars.end() && symbols_.is_domain_type(it->second.element_type))
          return it->second.element_type;
      }
    }
    return {};
  }

  // `prior_SaLe_gaussian`: the conditions' predicates and the term's name.
  static std::string prior_base(const ast::PriorDecl& p) {
    std::string s = "prior";
    for (const ast::Condition& c : p.conditions) s += "_" + cpp_identifier(c.atom.pred.name);
    return s + "_" + cpp_identifier(p.call.name);
  }

  void collect_prior_names() {
    std::map<std::string, int> count;
    for (const ast::Item& item : program_.modules.front().items)
      if (const auto* p = std::get_if<ast::PriorDecl>(&item.node); p != nullptr && p->quantified) ++count[prior_base(*p)];
    for (const ast::Item& item : program_.modules.front().items) {
      const auto* p = std::get_if<ast::PriorDecl>(&item.node);
      if (p == nullptr || !p->quantified) continue;
      std::string name = prior_base(*p);
      if (count[name] > 1) {  // same conditions and term: tell them apart by their text
        char hex[8];
        const std::uint32_t h = check::fnv1a(one_line(fmt::print_call(p->call)));
        std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>((h ^ (h >> 16)) & 0xffffu));
        name += std::string("_") + hex;
      }
      prior_names_[p] = name;
    }
  }

  std::string var_type(const std::string& var, const ast::PriorDecl& p) const {
    for (const ast::Condition& c : p.conditions) {
      const check::PredicateSym* ps = symbols_.predicate(c.atom.pred.name);
      for (std::size_t i = 0; ps != nullptr && i < c.atom.args.size() && i < ps->decl->args.size(); ++i)
        if (c.atom.args[i].name == var) return ps->decl->args[i].type.name;
    }
    return constant_type();
  }

  void functions(std::ostringstream& o) {
    for (const ast::Item& item : program_.modules.front().items) {
      if (const auto* x = std::get_if<ast::ExtractDecl>(&item.node)) {
        Frame f;
        for (std::size_t i = 0; i < x->target.args.size(); ++i) f.vars[x->target.args[i].name] = static_cast<int>(i);
        o << "// " << item_text(item) << "\n"
          << "bool extract_" << cpp_identifier(x->target.pred.name) << "(const Scene& s, const std::int32_t* c) {\n"
          << "  return " << call(x->call, f, true) << ";\n"
          << "}\n";
      } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node); p != nullptr && p->quantified) {
        Frame f;
        for (std::size_t i = 0; i < p->vars.size(); ++i) f.vars[p->vars[i].name] = static_cast<int>(i);
        o << "// " << item_text(item) << "\n"
          << "double " << prior_names_.at(p) << "(const Scene& s, const std::int32_t* c) {\n"
          << "  return " << call(p->call, f, true) << ";\n"
          << "}\n";
      }
    }
  }

  static std::string cmp(const std::string& op) {
    if (op == ">=") return "dom::Cmp::ge";
    if (op == "<") return "dom::Cmp::lt";
    if (op == "<=") return "dom::Cmp::le";
    return "dom::Cmp::gt";
  }

  std::string condition(const ast::Condition& k, const ast::PriorDecl& p) const {
    std::string vars = "{";
    for (std::size_t i = 0; i < k.atom.args.size(); ++i) {
      int index = 0;
      for (std::size_t v = 0; v < p.vars.size(); ++v)
        if (p.vars[v].name == k.atom.args[i].name) index = static_cast<int>(v);
      vars += (i ? ", " : "") + std::to_string(index);
    }
    vars += "}";
    return std::string("{") + (k.is_prob ? "true" : "false") + ", " + pred(k.atom.pred.name) + ", " + vars + ", " +
           cmp(k.op) + ", " + double_literal(k.is_prob ? k.threshold.value : 0.0) + ", " + (k.negated ? "true" : "false") +
           "}";
  }

  // The move the kernel's sources make (forward, reverse); empty when none does.
  std::pair<std::string, std::string> moves(const ast::KernelDecl& k) const {
    for (const ast::Call& c : k.sources) {
      auto it = symbols_.externs.find(c.name);
      if (it == symbols_.externs.end()) continue;
      const ast::MoveSpec& m = it->second.decl->moves;
      if (m.kind != ast::MoveSpec::Kind::Makes || m.moves.empty()) continue;
      return {m.moves.front().name, m.moves.back().name};
    }
    return {};
  }

  static std::string move(const std::string& m) { return m.empty() ? "blk::Move{}" : "blk::Move::" + block_identifier(m); }

  void item(std::ostringstream& o, const ast::Item& item) const {
    const Frame none;
    if (const auto* x = std::get_if<ast::ExtractDecl>(&item.node)) {
      const std::string p = cpp_identifier(x->target.pred.name);
      o << "  b.extractors.push_back({kPred_" << p << ", &extract_" << p << ", " << cpp_string(item_text(item)) << "});\n";
    } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node)) {
      if (!p->quantified) {
        o << "  b.priors.push_back(" << call(p->call, none, is_term_prior(p->call.name)) << ");\n";
        return;
      }
      std::string types = "{";
      for (std::size_t i = 0; i < p->vars.size(); ++i) types += (i ? ", " : "") + std::string("kType_") + cpp_identifier(var_type(p->vars[i].name, *p));
      types += "}";
      std::string conds = "{";
      for (std::size_t i = 0; i < p->conditions.size(); ++i) conds += (i ? ", " : "") + condition(p->conditions[i], *p);
      conds += "}";
      o << "  b.conditional_priors.push_back({" << types << ", " << conds << ", &" << prior_names_.at(p) << ", "
        << cpp_string(item_text(item)) << "});\n";
    } else if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
      o << "  b.likelihood = " << call(l->call, none, false) << ";\n";
    } else if (const auto* out = std::get_if<ast::OutputDecl>(&item.node)) {
      o << "  b.outputs.push_back(" << call(out->call, none, false) << ");\n";
    } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
      Frame f;
      for (const ast::KernelParam& kp : k->params) f.kernel_params.insert(kp.name.name);
      std::string sources = "{";
      for (std::size_t i = 0; i < k->sources.size(); ++i) sources += (i ? ", " : "") + call(k->sources[i], f, false);
      sources += "}";
      const std::string reverse = k->reverse ? k->reverse->name : k->name.name;
      const auto [forward_move, reverse_move] = moves(*k);
      const std::string text = cpp_string(item_text(item));
      o << "  b.kernels.push_back({" << cpp_string(k->name.name) << ", " << cpp_string(reverse) << ", "
        << move(forward_move) << ", " << sources << ", " << text << "});\n";
      if (k->pair && reverse != k->name.name)
        o << "  b.kernels.push_back({" << cpp_string(reverse) << ", " << cpp_string(k->name.name) << ", "
          << move(reverse_move) << ", b.kernels.back().sources, " << text << "});\n";
    } else if (const auto* s = std::get_if<ast::ScheduleDecl>(&item.node)) {
      for (const ast::ScheduleRow& r : s->rows) {
        const std::string begin = r.has_range ? lower::format_weight(r.lo.value) : "0";
        const std::string end = (!r.has_range || r.hi_inf) ? "dom::ScheduleRow::kForever" : lower::format_weight(r.hi.value);
        o << "  b.schedule.push_back({" << begin << ", " << end << ", {";
        for (std::size_t i = 0; i < r.entries.size(); ++i)
          o << (i ? ", " : "") << "{" << cpp_string(r.entries[i].kernel.name) << ", "
            << double_literal(r.entries[i].prob.value) << "}";
        o << "}});\n";
      }
    }
  }

  std::string source() {
    collect_prior_names();
    std::ostringstream o;
    o << "// Generated by ksmc from " << main_path() << ": the binding of domain `" << symbols_.domain
      << "` to the stdlib kit `" << kit_ << "`.\n"
      << "// Do not edit: change the domain file and run `ksmc emit` again.\n"
      << "#include \"" << ns_ << "_model.h\"\n\n"
      << "#include <cstdint>\n"
      << "#include <limits>\n\n"
      << "#include \"" << ns_ << "_factors.h\"\n"
      << "#include \"stdlib/" << kit_ << "/blocks.h\"\n\n"
      << "namespace ksmc_generated::" << ns_ << " {\n"
      << "namespace {\n\n"
      << "namespace blk = ksmc::stdlib::" << cpp_identifier(kit_) << "::blocks;\n"
      << "namespace dom = ksmc::runtime::domain;\n"
      << "using Scene = blk::Scene;\n\n";
    functions(o);
    o << "\n"
      << "blk::Binding make_binding() {\n"
      << "  blk::Binding b;\n"
      << "  b.domain = " << cpp_string(symbols_.domain) << ";\n"
      << "  b.source = " << cpp_string(main_path()) << ";\n"
      << "  b.mln = {&program, &make_domain, &ground};\n";
    const std::string ct = constant_type();
    if (!ct.empty()) o << "  b.constant_type = kType_" << cpp_identifier(ct) << ";\n";
    for (const ast::Item& it : program_.modules.front().items) item(o, it);
    o << "  return b;\n"
      << "}\n\n"
      << "}  // namespace\n\n"
      << "const blk::Binding& binding() {\n"
      << "  static const blk::Binding b = make_binding();\n"
      << "  return b;\n"
      << "}\n\n"
      << "}  // namespace ksmc_generated::" << ns_ << "\n";
    return o.str();
  }

  std::string main_file() const {
    std::ostringstream o;
    o << "// Generated by ksmc from " << main_path() << ": entry point of the `" << symbols_.domain << "` binary.\n"
      << "// Do not edit: change the domain file and run `ksmc emit` again.\n"
      << "#include \"" << ns_ << "_model.h\"\n"
      << "#include \"runtime/cli/domain_main.h\"\n"
      << "#include \"stdlib/" << kit_ << "/kit/kit.h\"\n\n"
      << "int main(int argc, char** argv) {\n"
      << "  return ksmc::runtime::cli::run_domain_main(\n"
      << "      argc, argv, ksmc::stdlib::" << cpp_identifier(kit_) << "::kit::domain_spec(ksmc_generated::" << ns_
      << "::binding()));\n"
      << "}\n";
    return o.str();
  }

  const ast::Program& program_;
  const check::SymbolTable& symbols_;
  const diag::SourceManager& sources_;
  std::string kit_;
  std::string ns_;
  std::map<const ast::PriorDecl*, std::string> prior_names_;
};

}  // namespace

std::string kit_of(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources) {
  (void)sources;
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

ModelOutput emit_model(const ast::Program& program, const check::SymbolTable& symbols,
                       const diag::SourceManager& sources, const std::string& kit) {
  return ModelEmitter(program, symbols, sources, kit).run();
}

}  // namespace ksmc::compiler::emit
