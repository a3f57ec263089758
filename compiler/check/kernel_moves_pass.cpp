// Which move a kernel makes: its sources make exactly one move declaration (`makes F / R`
// or `makes M`; several sources may make the same), `serves` sources serve it, and the
// kernel's shape fits the move: `kernel pair A / B` a pair move (A forward, B reverse) or a
// self-reverse one, `kernel K reverse K` a self-reverse move.
#include "compiler/check/passes.h"

namespace ksmc::compiler::check {
namespace {

std::string moves_text(const ast::MoveSpec& m) {
  std::string s;
  const bool makes = m.kind == ast::MoveSpec::Kind::Makes;
  for (std::size_t i = 0; i < m.moves.size(); ++i) s += (i ? (makes ? " / " : ", ") : "") + m.moves[i].name;
  return s;
}

bool same(const ast::MoveSpec& a, const ast::MoveSpec& b) {
  if (a.moves.size() != b.moves.size()) return false;
  for (std::size_t i = 0; i < a.moves.size(); ++i)
    if (a.moves[i].name != b.moves[i].name) return false;
  return true;
}

void kernel(Context& ctx, const ast::KernelDecl& k, const ast::Loc& at) {
  if (!k.pair && k.reverse && k.reverse->name != k.name.name) return;  // the kernels pass refused it
  if (k.sources.empty()) {
    ctx.diags.error(at, "kernel '" + k.name.name + "' has no proposal source; write 'kernel ... = source(...), ...;'");
    return;
  }
  const ast::MoveSpec* move = nullptr;
  const ast::Call* maker = nullptr;
  std::vector<std::pair<const ast::Call*, const ast::MoveSpec*>> helpers;
  for (const ast::Call& c : k.sources) {
    auto it = ctx.symbols.externs.find(c.name);
    if (it == ctx.symbols.externs.end() || it->second.decl->kind.name != "proposal") continue;  // the calls pass reported it
    const ast::MoveSpec& m = it->second.decl->moves;
    if (m.kind == ast::MoveSpec::Kind::None) {
      ctx.diags.error(c.loc, "proposal '" + c.name + "' declares no move: its signature needs 'makes ...' or 'serves ...'");
    } else if (m.kind == ast::MoveSpec::Kind::Serves) {
      helpers.emplace_back(&c, &m);
    } else if (move == nullptr) {
      move = &m;
      maker = &c;
    } else if (!same(*move, m)) {
      ctx.diags.error(c.loc, "'" + c.name + "' makes " + moves_text(m) + ", but '" + maker->name + "' in the same kernel makes " +
                                 moves_text(*move) + "; the sources of a kernel make one move");
    }
  }
  if (move == nullptr) {
    if (!k.sources.empty() && helpers.size() == k.sources.size())
      ctx.diags.error(at, "no source of kernel '" + k.name.name + "' makes a move (they only serve one); add a proposal that 'makes' it");
    return;
  }
  for (const auto& [c, m] : helpers) {
    bool serves = false;
    for (const ast::Ident& s : m->moves)
      for (const ast::Ident& mv : move->moves) serves = serves || s.name == mv.name;
    if (!serves) {
      ctx.diags.error(c->loc, "'" + c->name + "' serves " + moves_text(*m) + ", not the move " + moves_text(*move) +
                                  " that '" + maker->name + "' makes");
    }
  }
  const bool self_reverse = move->moves.size() == 1;
  if (!k.pair && !self_reverse) {
    ctx.diags.error(maker->loc, "'" + maker->name + "' makes the pair move " + moves_text(*move) + "; kernel '" + k.name.name +
                                    "' is its own reverse: declare 'kernel pair " + k.name.name + " / NAME = ...;'");
  }
}

}  // namespace

void KernelMovesPass::run(Context& ctx) {
  for (const ast::Item& item : ctx.main().items)
    if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) kernel(ctx, *k, item.loc);
}

}  // namespace ksmc::compiler::check
