# Fault injection with strace (sourced by run.sh; issue 16): a run killed with SIGKILL at each
# rename of its outputs and after the folder swap, and a full disk. A kill before the swap
# leaves the previous complete folder; a kill after it, the new complete one; never a mix.
# Skipped where strace is missing or may not trace (no ptrace in the container).

run_fault_cases() {
  local toy="$1/ksmc_toy_domain"
  local st=(strace -f -qq -o /dev/null)
  if ! command -v strace > /dev/null || ! strace -qq -o /dev/null true 2> /dev/null; then
    skip "fault injection (SIGKILL at rename, full disk)" "strace missing or ptrace not permitted"
    return
  fi
  printf '{"n": 20, "start": 2}' > toy.json
  # The renames of a run with --trace over an existing folder: one rename() per file inside
  # the staging folder, then the swap, renameat2(RENAME_EXCHANGE). (strace counts `when` per
  # system call, so each kind is aimed at separately.)
  "$toy" toy.json --iterations 100 --quiet --out probe > /dev/null 2>&1
  strace -qq -o renames.log -e trace=rename,renameat2 "$toy" toy.json --iterations 100 --trace --quiet --out probe > /dev/null 2>&1
  local n
  n=$(grep -c '^rename(' renames.log)
  grep -q '^renameat2(.*RENAME_EXCHANGE' renames.log || { failed=$((failed + 1)); echo "FAIL no folder swap (renameat2 RENAME_EXCHANGE) in renames.log"; }
  "$toy" toy.json --iterations 100 --quiet --out kr > /dev/null 2>&1  # the previous complete folder
  for k in $(seq 1 "$n"); do
    expect "SIGKILL at file rename $k of $n" 137 "" intact kr -- \
      "${st[@]}" -e trace=rename -e inject=rename:signal=KILL:when=$k "$toy" toy.json --iterations 3000 --trace --quiet --out kr
  done
  expect "SIGKILL at the folder swap" 137 "" intact kr -- \
    "${st[@]}" -e trace=renameat2 -e inject=renameat2:signal=KILL:when=1 "$toy" toy.json --iterations 3000 --trace --quiet --out kr
  expect "the next run removes what the kills left" 0 "" complete kr -- "$toy" toy.json --iterations 100 --quiet --out kr
  # The swap is done; the kill comes while the previous folder (now the staging name) is deleted.
  expect "SIGKILL after the swap" 137 "" - kr -- \
    "${st[@]}" -e trace=unlink,unlinkat,rmdir -e inject=unlink,unlinkat:signal=KILL:when=1 "$toy" toy.json --iterations 3000 --trace --quiet --out kr
  cases=$((cases + 1))
  if [ -f kr/trace.csv ] && [ -f kr/summary.json ]; then
    echo "ok   after the swap the new complete folder is in place"
  else
    failed=$((failed + 1)); echo "FAIL after the swap: kr holds $(ls kr | tr '\n' ' ')"
  fi
  manifest_complete kr "after the swap: every file listed"
  expect "the next run removes the previous folder's remains" 0 "" complete kr -- "$toy" toy.json --iterations 100 --quiet --out kr
  # A full disk: every write fails from the first (or the fifth) on. The run fails (its message
  # cannot be written either) and the previous folder stays.
  # (Not under AddressSanitizer: its runtime write()s to internal pipes and dies when they fail.)
  # (Read whole, not piped into grep -q: under pipefail, ldd killed by SIGPIPE when grep
  # exits at the first match would make the test miss the sanitizer, now and then.)
  local libs
  libs=$(ldd "$toy" 2> /dev/null || true)
  if [[ "$libs" == *libasan* ]]; then
    skip "full disk (ENOSPC)" "sanitized build: the ASan runtime's own writes would fail"
    return
  fi
  for first in 1 5; do
    expect "full disk from write $first on" 1 "" intact kr -- \
      "${st[@]}" -e trace=write,writev,pwrite64 -e inject=write,writev,pwrite64:error=ENOSPC:when=$first+ "$toy" toy.json --iterations 3000 --trace --quiet --out kr
  done
}
