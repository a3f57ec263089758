#include "compiler/emit/emit_model.h"

#include <cmath>
#include <sstream>

#include "compiler/lower/dump_ir.h"

namespace ksmc::compiler::emit {
namespace {

std::string one_line(std::string_view text) {
  std::string out;
  bool space = false;
  for (char ch : text) {
    if (ch == '\n' || ch == '\r' || ch == '\t' || ch == ' ') {
      space = !out.empty();
      continue;
    }
    if (space) out.push_back(' ');
    space = false;
    out.push_back(ch);
  }
  return out;
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
  const std::string& main_path() const { return program_.modules.front().path; }

  std::string where(const ast::Loc& loc) const { return sources_.path(loc.file) + ":" + std::to_string(loc.line); }

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

  std::string value(const ast::Expr& e) const {
    using K = ast::Expr::Kind;
    switch (e.kind) {
      case K::Number:
        return "V::num(" + lower::format_weight(e.number.value * unit_scale(e.number.unit)) + ")";
      case K::String:
        return "V::str(" + cpp_string(e.text) + ")";
      case K::Bool:
        return std::string("V::flag(") + (e.text == "true" ? "true" : "false") + ")";
      case K::Inf:
        return "V::num(kInf)";
      case K::Name:
        return "V::name(" + cpp_string(e.text) + ")";
      case K::Index:
        return "V::index(" + cpp_string(e.text) + ", {V::name(" + cpp_string(e.index.name) + ")})";
      case K::Call: {
        std::string s = "V::call(" + cpp_string(e.call->name) + ", {";
        for (std::size_t i = 0; i < e.call->args.size(); ++i) s += (i ? ", " : "") + value(e.call->args[i].value);
        return s + "})";
      }
      case K::List:
      case K::Set: {
        std::string s = e.kind == K::List ? "V::list({" : "V::set({";
        for (std::size_t i = 0; i < e.items.size(); ++i) s += (i ? ", " : "") + value(e.items[i]);
        return s + "})";
      }
    }
    return "V{}";
  }

  // A stdlib call with its arguments matched to the declared parameters, defaults filled in.
  std::string call(const ast::Call& c) const {
    std::string s = "{" + cpp_string(c.name) + ", {";
    auto ext = symbols_.externs.find(c.name);
    bool first = true;
    auto arg = [&](const std::string& name, const std::string& v) {
      s += (first ? "" : ", ") + std::string("{") + cpp_string(name) + ", " + v + "}";
      first = false;
    };
    if (ext != symbols_.externs.end() && ext->second.decl != nullptr) {
      const auto& params = ext->second.decl->params;
      std::size_t positional = 0;
      for (const ast::Param& p : params) {
        const ast::Arg* found = nullptr;
        for (const ast::Arg& a : c.args)
          if (a.name && a.name->name == p.name.name) found = &a;
        if (found == nullptr) {
          std::size_t seen = 0;
          for (const ast::Arg& a : c.args) {
            if (a.name) continue;
            if (seen++ == positional) {
              found = &a;
              break;
            }
          }
          if (found != nullptr) ++positional;
        }
        if (found != nullptr) arg(p.name.name, value(found->value));
        else if (p.default_value) arg(p.name.name, value(*p.default_value));
      }
    } else {
      for (const ast::Arg& a : c.args) arg(a.name ? a.name->name : std::string(), value(a.value));
    }
    return s + "}, " + cpp_string(where(c.loc)) + "}";
  }

  static std::string strings(const std::vector<std::string>& v) {
    std::string s = "{";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + cpp_string(v[i]);
    return s + "}";
  }

  std::string header() const {
    std::ostringstream o;
    o << "// Generated by ksmc from " << main_path() << ": the domain's configuration for its stdlib kit.\n"
      << "// Do not edit: change the domain file and run `ksmc emit` again.\n"
      << "#pragma once\n\n"
      << "#include \"runtime/domain/config.h\"\n\n"
      << "namespace ksmc_generated::" << ns_ << " {\n\n"
      << "// Every model, extract, prior, likelihood, kernel and schedule item of the domain file.\n"
      << "const ksmc::runtime::domain::DomainConfig& domain_config();\n\n"
      << "// The generated Markov logic part (" << ns_ << "_factors.h).\n"
      << "ksmc::runtime::domain::MlnBinding mln_binding();\n\n"
      << "}  // namespace ksmc_generated::" << ns_ << "\n";
    return o.str();
  }

  std::string source() const {
    std::ostringstream o;
    o << "// Generated by ksmc from " << main_path() << ": the domain's configuration for its stdlib kit.\n"
      << "// Do not edit: change the domain file and run `ksmc emit` again.\n"
      << "#include \"" << ns_ << "_model.h\"\n\n"
      << "#include <limits>\n\n"
      << "#include \"" << ns_ << "_factors.h\"\n\n"
      << "namespace ksmc_generated::" << ns_ << " {\n"
      << "namespace {\n\n"
      << "namespace domain = ksmc::runtime::domain;\n"
      << "using V = domain::Value;\n"
      << "[[maybe_unused]] constexpr double kInf = std::numeric_limits<double>::infinity();\n"
      << "constexpr std::int64_t kForever = domain::ScheduleRow::kForever;\n\n"
      << "domain::DomainConfig make_config() {\n"
      << "  domain::DomainConfig c;\n"
      << "  c.domain = " << cpp_string(symbols_.domain) << ";\n"
      << "  c.source = " << cpp_string(main_path()) << ";\n";
    for (const ast::Item& item : program_.modules.front().items) emit_item(o, item);
    o << "  return c;\n"
      << "}\n\n"
      << "}  // namespace\n\n"
      << "const domain::DomainConfig& domain_config() {\n"
      << "  static const domain::DomainConfig config = make_config();\n"
      << "  return config;\n"
      << "}\n\n"
      << "domain::MlnBinding mln_binding() { return {&program, &make_domain, &ground}; }\n\n"
      << "}  // namespace ksmc_generated::" << ns_ << "\n";
    return o.str();
  }

  void emit_item(std::ostringstream& o, const ast::Item& item) const {
    const auto comment = [&] { o << "  // " << where(item.loc) << ": " << item_text(item) << "\n"; };
    if (const auto* m = std::get_if<ast::ModelDecl>(&item.node)) {
      o << "  // " << where(item.loc) << ": model " << m->name.name << "\n";
      for (const ast::ModelVar& v : m->vars) {
        o << "  c.model.push_back({" << cpp_string(v.name.name) << ", " << (v.collection ? "true" : "false") << ", "
          << cpp_string(v.index ? v.index->name : std::string()) << ", " << cpp_string(v.type.name) << ", "
          << (v.sampled ? "true" : "false") << "});\n";
      }
    } else if (const auto* x = std::get_if<ast::ExtractDecl>(&item.node)) {
      comment();
      std::vector<std::string> vars;
      for (const auto& a : x->target.args) vars.push_back(a.name);
      o << "  c.extract.push_back({" << cpp_string(x->target.pred.name) << ", " << strings(vars) << ", " << call(x->call)
        << "});\n";
    } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node)) {
      comment();
      std::vector<std::string> vars;
      for (const auto& v : p->vars) vars.push_back(v.name);
      std::string conds = "{";
      for (std::size_t i = 0; i < p->conditions.size(); ++i) {
        const ast::Condition& k = p->conditions[i];
        std::vector<std::string> args;
        for (const auto& a : k.atom.args) args.push_back(a.name);
        conds += (i ? ", " : "") + std::string("{") + (k.is_prob ? "true" : "false") + ", " + (k.negated ? "true" : "false") +
                 ", " + cpp_string(k.atom.pred.name) + ", " + strings(args) + ", " + cpp_string(k.op) + ", " +
                 lower::format_weight(k.is_prob ? k.threshold.value : 0.0) + "}";
      }
      conds += "}";
      o << "  c.prior.push_back({" << strings(vars) << ", " << conds << ", " << call(p->call) << "});\n";
    } else if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
      comment();
      o << "  c.likelihood.push_back(" << call(l->call) << ");\n";
    } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
      comment();
      std::string params = "{";
      for (std::size_t i = 0; i < k->params.size(); ++i)
        params += (i ? ", " : "") + std::string("{") + cpp_string(k->params[i].name.name) + ", " +
                  cpp_string(k->params[i].type.name) + "}";
      params += "}";
      std::string sources = "{";
      for (std::size_t i = 0; i < k->sources.size(); ++i) sources += (i ? ", " : "") + call(k->sources[i]);
      sources += "}";
      const std::string reverse = k->reverse ? k->reverse->name : k->name.name;
      const std::string at = cpp_string(where(item.loc));
      o << "  c.kernels.push_back({" << cpp_string(k->name.name) << ", " << cpp_string(reverse) << ", " << params << ", "
        << sources << ", " << at << "});\n";
      if (k->pair)
        o << "  c.kernels.push_back({" << cpp_string(reverse) << ", " << cpp_string(k->name.name) << ", " << params
          << ", c.kernels.back().sources, " << at << "});\n";
    } else if (const auto* s = std::get_if<ast::ScheduleDecl>(&item.node)) {
      o << "  // " << where(item.loc) << ": schedule\n";
      for (const ast::ScheduleRow& r : s->rows) {
        const std::string begin = r.has_range ? lower::format_weight(r.lo.value) : "0";
        const std::string end = (!r.has_range || r.hi_inf) ? "kForever" : lower::format_weight(r.hi.value);
        o << "  c.schedule.push_back({" << begin << ", " << end << ", {";
        for (std::size_t i = 0; i < r.entries.size(); ++i)
          o << (i ? ", " : "") << "{" << cpp_string(r.entries[i].kernel.name) << ", "
            << lower::format_weight(r.entries[i].prob.value) << "}";
        o << "}});  // " << where(r.loc) << "\n";
      }
    }
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
      << "      argc, argv,\n"
      << "      ksmc::stdlib::" << cpp_identifier(kit_) << "::kit::domain_spec(ksmc_generated::" << ns_
      << "::domain_config(), ksmc_generated::" << ns_ << "::mln_binding()));\n"
      << "}\n";
    return o.str();
  }

  const ast::Program& program_;
  const check::SymbolTable& symbols_;
  const diag::SourceManager& sources_;
  std::string kit_;
  std::string ns_;
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
