#!/usr/bin/python3
"""Coordinate search over rule weights of domains/tabletop.ksm, scored by the kit itself.

Each step sets one rule's `prob` to its neighbour on a ladder, rebuilds tabletop_family_eval
(the weights are compiled in), scores training scenes of both generators and keeps the step
when the objective rises by at least --min-gain. The objective is the sum of four pooled F1:
false and hidden estimates on the independent generator and on the project's generator, each
pooled over the families (the exact counts of the eval's `pooled over` line).

The domain file is edited in place and restored at the end (also on an error or Ctrl-C); the
best file found is written to --out. Score the result on seeds the search did not see before
keeping any of it (docs/tabletop_families/base_rate_r22.md).

  scripts/tabletop_weight_search.py --build build --out /tmp/best.ksm --lines 49,57,58

--lines are the 1-based line numbers of the `prob` rules to search, in that order.
"""
import argparse
import os
import re
import subprocess
import sys

LADDER = [0.6, 0.65, 0.7, 0.75, 0.85, 0.9, 0.95, 0.99]


def weight(lines, i):
    return float(re.match(r'^prob ([0-9.]+):', lines[i]).group(1))


def with_weight(lines, i, w):
    out = list(lines)
    out[i] = re.sub(r'^prob [0-9.]+:', 'prob %g:' % w, out[i])
    return out


def pooled_f1s(out):
    """False and hidden F1 from tabletop_family_eval's `pooled over N families:` line."""
    line = next((l for l in out.split('\n') if l.startswith('pooled over ')), None)
    if line is None:
        raise RuntimeError('tabletop_family_eval printed no pooled line')
    f1 = {}
    for part in line.split(':', 1)[1].split('|'):
        m = re.match(r'\s*(\w+) P R F1 [0-9.]+ [0-9.]+ ([0-9.]+)', part)
        if m:
            f1[m.group(1)] = float(m.group(2))
    return [f1['false'], f1['hidden']]


def score(args):
    built = subprocess.run(['cmake', '--build', args.build, '-j2', '--target', 'tabletop_family_eval'],
                           stdout=subprocess.DEVNULL)
    if built.returncode:
        raise RuntimeError('building tabletop_family_eval in %s failed' % args.build)
    binary = os.path.join(args.build, 'bin', 'tabletop_family_eval')
    runs = [[binary, '--generator', 'indep', '--scenes', str(args.indep_scenes), '--seed', str(args.indep_seed)],
            [binary, '--scenes', str(args.project_scenes), '--seed', str(args.project_seed)]]
    procs = [subprocess.Popen(r, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True) for r in runs]
    parts = []
    for p in procs:
        out, _ = p.communicate()
        if p.returncode:
            raise RuntimeError('tabletop_family_eval failed')
        parts += pooled_f1s(out)
    return sum(parts), parts


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--build', default='build')
    ap.add_argument('--domain', default='domains/tabletop.ksm')
    ap.add_argument('--out', required=True, help='the best domain file found')
    ap.add_argument('--lines', required=True, help="comma-separated line numbers of `prob` rules, in search order")
    ap.add_argument('--indep-seed', type=int, default=5)
    ap.add_argument('--indep-scenes', type=int, default=30)
    ap.add_argument('--project-seed', type=int, default=5)
    ap.add_argument('--project-scenes', type=int, default=20)
    ap.add_argument('--min-gain', type=float, default=0.006)
    args = ap.parse_args()

    original = open(args.domain).read()
    lines = original.split('\n')
    steps = []
    for number in args.lines.split(','):
        i = int(number) - 1 if number.isdigit() else -1
        if not 0 <= i < len(lines) or not lines[i].startswith('prob '):
            sys.exit('%s:%s: not a `prob` rule' % (args.domain, number))
        if weight(lines, i) not in LADDER:
            sys.exit('%s:%s: weight %g is not on the ladder %s' % (args.domain, number, weight(lines, i), LADDER))
        steps.append((number, i))
    try:
        best, parts = score(args)
        print('start: J %.4f %s' % (best, ' '.join('%.3f' % x for x in parts)), flush=True)
        for number, i in steps:
            name = 'line %s' % number
            w = weight(lines, i)
            k = LADDER.index(w)
            for j in (k - 1, k + 1):
                if not 0 <= j < len(LADDER):
                    continue
                candidate = with_weight(lines, i, LADDER[j])
                open(args.domain, 'w').write('\n'.join(candidate))
                value, parts = score(args)
                print('%s %g -> %g: J %.4f (%+.4f) %s' % (name, w, LADDER[j], value, value - best,
                                                         ' '.join('%.3f' % x for x in parts)), flush=True)
                if value >= best + args.min_gain:
                    best, lines = value, candidate
                    print('  kept', flush=True)
                    break
            open(args.domain, 'w').write('\n'.join(lines))
        open(args.out, 'w').write('\n'.join(lines))
        print('best: J %.4f, written to %s' % (best, args.out))
    except RuntimeError as e:
        sys.exit('tabletop_weight_search: %s' % e)
    finally:
        open(args.domain, 'w').write(original)
    return 0


if __name__ == '__main__':
    sys.exit(main())
