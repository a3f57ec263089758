#include "compiler/fmt/formatter.h"

#include <algorithm>

#include "compiler/fmt/printer.h"

namespace ksmc::compiler::fmt {

namespace {

int last_line(const ast::Comment& c) {
  return c.loc.line + static_cast<int>(std::count(c.text.begin(), c.text.end(), '\n'));
}

class Formatter {
 public:
  explicit Formatter(const ast::Module& m) : m_(m) {}

  std::string run() {
    for (const ast::Item& item : m_.items) {
      const bool block = std::holds_alternative<ast::ModelDecl>(item.node) ||
                         std::holds_alternative<ast::ScheduleDecl>(item.node);
      leading(item.loc.offset, "");
      if (!block) hoist(item.end_offset, item.loc.line, "");
      gap(item.loc.line);
      block_end_ = item.end_offset;
      std::visit([&](const auto& n) { emit(n); }, item.node);
      trailing(item.end_line);
      out_ += '\n';
      last_ = item.end_line;
    }
    leading(SIZE_MAX, "");
    return out_;
  }

 private:
  // A blank line when the source had one before `line`.
  void gap(int line) {
    if (last_ > 0 && line > last_ + 1 && !out_.empty()) out_ += '\n';
  }

  void comment_line(const ast::Comment& c, const std::string& indent) {
    out_ += indent + c.text + '\n';
  }

  // Comments before `offset` become whole lines at `indent`.
  void leading(std::size_t offset, const std::string& indent) {
    while (next_ < m_.comments.size() && m_.comments[next_].loc.offset < offset) {
      const ast::Comment& c = m_.comments[next_++];
      gap(c.loc.line);
      comment_line(c, indent);
      last_ = last_line(c);
    }
  }

  // Comments inside a declaration printed on one line move above it.
  void hoist(std::size_t end, int item_line, const std::string& indent) {
    bool first = true;
    while (next_ < m_.comments.size() && m_.comments[next_].loc.offset < end) {
      const ast::Comment& c = m_.comments[next_];
      if (first) gap(item_line);
      first = false;
      comment_line(c, indent);
      ++next_;
      last_ = item_line;  // the declaration follows directly
    }
  }

  // Comments after a declaration on its last line stay at the end of that line.
  void trailing(int line) {
    while (next_ < m_.comments.size() && m_.comments[next_].loc.line == line &&
           m_.comments[next_].text.find('\n') == std::string::npos) {
      out_ += "  " + m_.comments[next_++].text;
    }
  }

  void emit(const ast::DomainDecl& d) { out_ += "domain " + d.name.name + ";"; }
  void emit(const ast::IncludeDecl& i) { out_ += "include " + quote_string(i.path) + ";"; }
  void emit(const ast::TypeDecl& t) {
    out_ += "type " + t.name.name;
    if (t.enumerated) {
      out_ += " = {";
      for (std::size_t i = 0; i < t.constants.size(); ++i) out_ += (i ? ", " : "") + t.constants[i].name;
      out_ += "}";
    }
    out_ += ";";
  }
  void emit(const ast::PredDecl& d) {
    out_ += d.query ? "query " : "evidence ";
    for (std::size_t i = 0; i < d.preds.size(); ++i) {
      const ast::PredSig& p = d.preds[i];
      out_ += (i ? ", " : "") + p.name.name + "(";
      for (std::size_t j = 0; j < p.args.size(); ++j) {
        out_ += (j ? ", " : "") + p.args[j].type.name + (p.args[j].exclusive ? "!" : "");
      }
      out_ += ")";
    }
    out_ += ";";
  }
  void emit(const ast::QuantityDecl& q) {
    out_ += "quantity " + q.name.name;
    if (!q.units.empty()) {
      out_ += " [";
      for (std::size_t i = 0; i < q.units.size(); ++i) {
        out_ += (i ? ", " : "") + q.units[i].name.name + " = " + print_number(q.units[i].scale);
      }
      out_ += "]";
    }
    out_ += ";";
  }
  void emit(const ast::ValueDecl& v) {
    out_ += "value ";
    for (std::size_t i = 0; i < v.names.size(); ++i) out_ += (i ? ", " : "") + v.names[i].name;
    out_ += ";";
  }
  void emit(const ast::ExternDecl& x) {
    out_ += "extern " + x.kind.name + " " + x.name;
    if (x.has_params) {
      out_ += "(";
      for (std::size_t i = 0; i < x.params.size(); ++i) {
        const ast::Param& p = x.params[i];
        out_ += (i ? ", " : "") + p.name.name + ": " + print_type(p.type);
        if (p.range) {
          out_ += std::string(" in ") + (p.range->lo_open ? "(" : "[") + bound(p.range->lo) + ", " + bound(p.range->hi) +
                  (p.range->hi_open ? ")" : "]");
        }
        if (p.rowsum) out_ += " rowsum " + print_number(*p.rowsum);
        if (p.default_value) out_ += " = " + print_expr(*p.default_value);
      }
      out_ += ")";
    }
    if (x.result) out_ += " -> " + print_type(*x.result);
    if (x.reads) out_ += " reads " + print_type(*x.reads);
    if (x.moves.kind != ast::MoveSpec::Kind::None) {
      const bool makes = x.moves.kind == ast::MoveSpec::Kind::Makes;
      out_ += makes ? " makes " : " serves ";
      for (std::size_t i = 0; i < x.moves.moves.size(); ++i) out_ += (i ? (makes ? " / " : ", ") : "") + x.moves.moves[i].name;
    }
    out_ += ";";
  }
  static std::string bound(const ast::Bound& b) {
    return b.inf ? (b.negative ? "-inf" : "inf") : print_number(b.number);
  }
  void emit(const ast::ModelContractDecl& d) {
    out_ += "extern model(";
    for (std::size_t i = 0; i < d.slots.size(); ++i) {
      const ast::ModelSlot& s = d.slots[i];
      out_ += (i ? ", " : "") + s.type.name;
      if (s.collection) out_ += "[" + (s.index ? s.index->name : std::string()) + "]";
      out_ += s.sampled ? " sampled" : " fixed";
    }
    out_ += ");";
  }
  void emit(const ast::OutputDecl& o) { out_ += "output " + print_call(o.call) + ";"; }
  void emit(const ast::Rule& r) {
    std::string head;
    if (r.label) head += "@" + r.label->name + " ";
    if (r.hard) head += "hard ";
    if (r.prob) head += "prob " + print_number(*r.prob) + ": ";
    if (r.weight) head += "w " + print_number(*r.weight) + ": ";
    out_ += head;
    if (r.exactly_one) {
      out_ += "exactly one of ";
      for (std::size_t i = 0; i < r.alternatives.size(); ++i) out_ += (i ? ", " : "") + print_atom(r.alternatives[i]);
    } else {
      out_ += print_formula(r.formula);
    }
    out_ += ".";
  }
  void emit(const ast::ModelDecl& m) {
    out_ += "model " + m.name.name + " {\n";
    last_ = 0;
    for (const ast::ModelVar& v : m.vars) {
      leading(v.loc.offset, "  ");
      hoist(v.end_offset, v.loc.line, "  ");
      gap(v.loc.line);
      out_ += "  " + v.name.name;
      if (v.collection) out_ += "[" + (v.index ? v.index->name : std::string()) + "]";
      out_ += " : " + print_type(v.type) + (v.sampled ? " sampled;" : " fixed;");
      trailing(v.end_line);
      out_ += '\n';
      last_ = v.end_line;
    }
    close_block();
  }
  // Rows print one per line; the short input form `schedule { a: 1.0 }` prints as a row
  // without range, `{ a: 1.0 };`, so its line is stable when ranges are added later.
  void emit(const ast::ScheduleDecl& s) {
    out_ += "schedule {\n";
    last_ = 0;
    for (const ast::ScheduleRow& r : s.rows) {
      leading(r.loc.offset, "  ");
      hoist(r.end_offset, r.loc.line, "  ");
      gap(r.loc.line);
      out_ += "  ";
      if (r.has_range) out_ += "[" + print_number(r.lo) + ", " + (r.hi_inf ? std::string("inf") : print_number(r.hi)) + "): ";
      out_ += "{";
      for (std::size_t i = 0; i < r.entries.size(); ++i) {
        out_ += std::string(i ? ", " : " ") + r.entries[i].kernel.name + ": " + print_number(r.entries[i].prob);
      }
      out_ += r.entries.empty() ? "};" : " };";
      trailing(r.end_line);
      out_ += '\n';
      last_ = r.end_line;
    }
    close_block();
  }
  // Comments before the closing brace stay inside the block.
  void close_block() {
    leading(block_end_, "  ");
    out_ += "}";
  }
  void emit(const ast::ExtractDecl& e) { out_ += "extract " + print_atom(e.target) + " = " + print_call(e.call) + ";"; }
  void emit(const ast::PriorDecl& p) {
    out_ += "prior ";
    if (p.quantified) {
      out_ += "for ";
      for (std::size_t i = 0; i < p.vars.size(); ++i) out_ += (i ? ", " : "") + p.vars[i].name;
      for (std::size_t i = 0; i < p.conditions.size(); ++i) {
        const ast::Condition& c = p.conditions[i];
        out_ += i ? " and " : " where ";
        if (c.is_prob) {
          out_ += c.fn.name + "(" + print_atom(c.atom) + ") " + c.op + " " + print_number(c.threshold);
        } else {
          out_ += (c.negated ? "!" : "") + print_atom(c.atom);
        }
      }
      out_ += ": ";
    }
    out_ += print_call(p.call) + ";";
  }
  void emit(const ast::LikelihoodDecl& l) { out_ += "likelihood " + print_call(l.call) + ";"; }
  void emit(const ast::KernelDecl& k) {
    out_ += "kernel ";
    if (k.pair) {
      out_ += "pair " + k.name.name + " / " + (k.reverse ? k.reverse->name : k.name.name);
    } else {
      out_ += k.name.name;
    }
    if (!k.params.empty()) {
      out_ += "(";
      for (std::size_t i = 0; i < k.params.size(); ++i) out_ += (i ? ", " : "") + k.params[i].name.name + ": " + k.params[i].type.name;
      out_ += ")";
    }
    if (!k.pair && k.reverse) out_ += " reverse " + k.reverse->name;
    if (k.sources.size() == 1) {
      out_ += " = " + print_call(k.sources.front());
    } else if (k.sources.size() > 1) {
      out_ += " =";
      for (std::size_t i = 0; i < k.sources.size(); ++i) out_ += "\n    " + print_call(k.sources[i]) + (i + 1 < k.sources.size() ? "," : "");
    }
    out_ += ";";
  }

  const ast::Module& m_;
  std::string out_;
  std::size_t next_ = 0;
  int last_ = 0;
  std::size_t block_end_ = 0;  // end offset of the block item being printed
};

}  // namespace

std::string format_module(const ast::Module& m) { return Formatter(m).run(); }

}  // namespace ksmc::compiler::fmt
