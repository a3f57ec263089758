# The cases of the bad-input suite (sourced by run.sh; runs in a scratch folder).
# expect NAME EXIT "MESSAGE FRAGMENT" none|intact|complete|- OUTPUT_DIR -- COMMAND...
# (a fragment "^text": the message starts with text)

# Every file of a complete output folder is listed in its summary.json with its SHA-256.
manifest_complete() {
  local dir="$1" name="$2"
  cases=$((cases + 1))
  local missing=""
  for f in $(cd "$dir" && find . -type f ! -name summary.json | sed 's|^\./||' | sort); do
    local h
    h="$(sha256sum "$dir/$f" | cut -d' ' -f1)"
    grep -q "\"sha256\": \"$h\"" "$dir/summary.json" || missing="$missing $f"
  done
  if [ -z "$missing" ]; then
    printf 'ok   %-48s every file listed with its SHA-256\n' "$name"
  else
    failed=$((failed + 1))
    printf 'FAIL %-48s not listed in summary.json:%s\n' "$name" "$missing"
  fi
}

run_cases() {
  local bin="$1" src="$2"
  local toy="$bin/ksmc_toy_domain" ksmc="$bin/ksmc"
  printf '{"n": 20, "start": 2}' > toy.json

  # ---- count flags: refused up front (exit 2), nothing written
  expect "--iterations -5" 2 "--iterations: expected a whole number from 1 to 18446744073709551615, got '-5' (negative)" none o1 -- "$toy" toy.json --iterations -5 --out o1
  expect "--iterations 0" 2 "--iterations: expected a whole number from 1" none o1 -- "$toy" toy.json --iterations 0 --out o1
  expect "--seed -1" 2 "--seed: expected a whole number from 0 to 18446744073709551615, got '-1' (negative)" none o1 -- "$toy" toy.json --seed -1 --out o1
  expect "--seed 99999999999999999999999" 2 "got '99999999999999999999999' (too large)" none o1 -- "$toy" toy.json --seed 99999999999999999999999 --out o1
  expect "--burn-in -1" 2 "--burn-in: expected a whole number from 0" none o1 -- "$toy" toy.json --burn-in -1 --out o1
  expect "--burn-in above --iterations" 2 "--burn-in 20 exceeds --iterations 10" none o1 -- "$toy" toy.json --burn-in 20 --iterations 10 --out o1
  expect "--samples -1" 2 "--samples: expected a whole number" none o1 -- "$toy" toy.json --samples -1 --out o1
  expect "--thin 0" 2 "--thin: expected a whole number from 1" none o1 -- "$toy" toy.json --thin 0 --out o1
  expect "--chains 0" 2 "--chains: expected a whole number from 1 to 4096" none o1 -- "$toy" toy.json --chains 0 --out o1
  expect "--threads -1" 2 "--threads: expected a whole number from 0 to 4096" none o1 -- "$toy" toy.json --threads -1 --out o1
  expect "--trace-every 1e3" 2 "--trace-every: expected a whole number" none o1 -- "$toy" toy.json --trace-every 1e3 --out o1

  # ---- inputs: regular files under the size limit
  mkdir -p adir
  expect "a folder as input" 1 "adir: expected a regular file, this is a folder" none o1 -- "$toy" adir --out o1
  expect "/dev/zero as input" 1 "/dev/zero: expected a regular file, this is a character device" none o1 -- "$toy" /dev/zero --out o1
  expect "missing input" 1 "nope.json: cannot open" none o1 -- "$toy" nope.json --out o1
  { printf '{"n": 20}'; head -c 1500000 /dev/zero | tr '\0' ' '; } > big.json
  expect "input over --max-input-mb" 1 "big.json: 1.5 MB exceeds the input size limit of 1 MB (raise it with --max-input-mb)" none o1 -- "$toy" big.json --max-input-mb 1 --out o1
  expect "ksmc check /dev/zero" 1 "larger than 64 MB" - - -- "$ksmc" check /dev/zero

  # ---- outputs: whole-folder atomic; the previous folder survives every failure
  expect "a good run" 0 "" complete good -- "$toy" toy.json --iterations 2000 --trace --samples 3 --out good
  manifest_complete good "summary.json lists every file"
  expect "bad flag keeps the previous outputs" 2 "--seed" intact good -- "$toy" toy.json --seed -1 --out good
  expect "bad input keeps the previous outputs" 1 "nope.json" intact good -- "$toy" nope.json --out good
  expect "rerun without --trace: no stale trace.csv" 0 "" complete good -- "$toy" toy.json --iterations 100 --out good
  cases=$((cases + 1))
  if [ -e good/trace.csv ] || [ -e good/samples.jsonl ]; then failed=$((failed + 1)); echo "FAIL stale files of the earlier run remain"; else echo "ok   no stale trace.csv / samples.jsonl"; fi
  mkdir -p mine && echo keep > mine/notes.txt
  expect "--out on a folder that is not an output" 1 "refusing to replace it" intact mine -- "$toy" toy.json --iterations 10 --out mine
  echo x > afile
  expect "--out below a file" 1 "afile/sub: cannot create output folder" none afile/sub -- "$toy" toy.json --iterations 10 --out afile/sub

  # ---- signals: complete outputs of the best state so far, exit 128 + signal
  expect "timeout -s INT 2" 130 "interrupted by SIGINT" complete sint -- timeout --foreground --preserve-status -s INT 2 "$toy" toy.json --iterations 100000000000 --trace --out sint
  grep -q '"interrupted": "SIGINT"' sint/summary.json 2>/dev/null || { failed=$((failed + 1)); echo "FAIL sint: no \"interrupted\": \"SIGINT\""; }
  expect "timeout -s TERM 2 (Slurm, roslaunch)" 143 "interrupted by SIGTERM" complete sterm -- timeout --foreground --preserve-status -s TERM 2 "$toy" toy.json --iterations 100000000000 --out sterm
  grep -q '"interrupted": "SIGTERM"' sterm/summary.json 2>/dev/null || { failed=$((failed + 1)); echo "FAIL sterm: no \"interrupted\": \"SIGTERM\""; }
  expect "timeout -s HUP 2" 129 "interrupted by SIGHUP" complete shup -- timeout --foreground --preserve-status -s HUP 2 "$toy" toy.json --iterations 100000000000 --out shup
  expect "SIGKILL keeps the previous outputs" 137 "" intact good -- timeout --foreground --preserve-status -s KILL 2 "$toy" toy.json --iterations 100000000000 --trace --out good
  expect "the next run removes what SIGKILL left" 0 "" complete good -- "$toy" toy.json --iterations 100 --out good

  # ---- readers name the file and the place
  local infer_dir="$src/tests/compiler/infer/seed_example_exact"
  local ksm="$src/domains/tabletop.ksm"
  cp "$infer_dir/evidence.db" ev.db
  expect "evidence: a folder" 1 "adir: error: evidence file expected, this is a folder" - - -- "$ksmc" infer "$ksm" --evidence adir --method exact
  { printf '\xef\xbb\xbf'; cat ev.db; } > bom.db
  expect "evidence: UTF-8 BOM is accepted" 0 "" - - -- "$ksmc" infer "$ksm" --evidence bom.db --method exact
  tr '\n' '\r' < ev.db > cr.db
  expect "evidence: CR-only line ends are accepted" 0 "" - - -- "$ksmc" infer "$ksm" --evidence cr.db --method exact
  cases=$((cases + 1))
  if [ "$("$ksmc" infer "$ksm" --evidence cr.db --method exact 2>/dev/null)" = "$("$ksmc" infer "$ksm" --evidence ev.db --method exact 2>/dev/null)" ]; then
    echo "ok   CR-only evidence gives the same answer as LF"
  else
    failed=$((failed + 1)); echo "FAIL CR-only evidence gives another answer than LF"
  fi
  { head -n 2 ev.db; printf 'stable(\0A)\n'; } > nul.db
  expect "evidence: NUL byte" 1 "nul.db:3: error: NUL byte at offset" - - -- "$ksmc" infer "$ksm" --evidence nul.db --method exact
  { printf '\xef\xbb\xbf'; cat "$ksm"; } > bom.ksm
  expect ".ksm: UTF-8 BOM is accepted" 0 "" - - -- "$ksmc" check -I "$src" bom.ksm
  tr '\n' '\r' < "$ksm" > cr.ksm
  expect ".ksm: CR-only line ends are accepted" 0 "" - - -- "$ksmc" check -I "$src" cr.ksm
  { head -n 3 "$ksm"; printf 'domain\0x;\n'; } > nul.ksm
  expect ".ksm: NUL byte" 1 "nul.ksm': NUL byte at line 4, column 7" - - -- "$ksmc" check -I "$src" nul.ksm

  # ---- ksmc fmt --in-place through a symbolic link keeps the link and the mode
  printf 'domain   d;\n' > real.ksm
  chmod 640 real.ksm
  ln -s real.ksm link.ksm
  expect "fmt --in-place on a symlink" 0 "" - - -- "$ksmc" fmt --in-place link.ksm
  cases=$((cases + 1))
  if [ -L link.ksm ] && [ "$(stat -c %a real.ksm)" = 640 ] && [ "$(cat real.ksm)" = "domain d;" ]; then
    echo "ok   link kept, mode 640 kept, target formatted"
  else
    failed=$((failed + 1)); echo "FAIL fmt --in-place: link $( [ -L link.ksm ] && echo kept || echo replaced ), mode $(stat -c %a real.ksm)"
  fi

  # ---- kits (when built)
  local tabletop="$bin/tabletop" indoor="$bin/indoor"
  if [ -x "$tabletop" ]; then
    cp "$src/examples/tabletop/seed_example.json" scene.json
    sed -E '0,/[0-9]+\.[0-9]+/s//1e999/' scene.json > overflow.json
    expect "scene.json: 1e999" 1 "overflow.json:" none t1 -- "$tabletop" overflow.json --out t1
    expect "scene.json: 1e999 names the number" 1 "number 1e999 is out of the range of a double" none t1 -- "$tabletop" overflow.json --out t1
    expect "tabletop SIGTERM mid-run" 143 "interrupted by SIGTERM" complete tterm -- timeout --foreground --preserve-status -s TERM 3 "$tabletop" scene.json --iterations 100000000000 --out tterm
    [ -d tterm ] && manifest_complete tterm "tabletop: every file listed (graph.png too)"
    expect "tabletop --max-ground-clauses 10" 1 "above the limit of 10; raise it with --max-ground-clauses" none tg -- "$tabletop" scene.json --max-ground-clauses 10 --out tg
    if command -v python3 >/dev/null; then
      # SIGINT 2 s into the initial inference of 1,000 mutually intersecting boxes: exit 130
      # within 4 s (the outer SIGKILL at 6 s gives 137 otherwise), the previous folder intact.
      python3 "$src/tests/badinput/make_crowded_scene.py" scene.json 1000 > crowded.json
      "$tabletop" scene.json --iterations 20 --quiet --out tcrowd >/dev/null 2>&1
      expect "tabletop SIGINT in initial inference" 130 "interrupted by SIGINT before a state existed" intact tcrowd -- \
        timeout -s KILL 6 timeout --foreground --preserve-status -s INT 2 "$tabletop" crowded.json --out tcrowd
    else
      skip "tabletop SIGINT in initial inference" "no python3 to write the crowded scene"
    fi
    # Large inputs: the estimate is refused above --max-memory-mb (figure and flag named).
    expect "--max-memory-mb 0" 2 "--max-memory-mb: expected a whole number from 1" none tm -- "$tabletop" scene.json --max-memory-mb 0 --out tm
    if command -v python3 >/dev/null; then
      python3 "$src/tests/badinput/make_crowded_scene.py" scene.json 200 > crowd200.json
      expect "tabletop scene above --max-memory-mb" 1 "crowd200.json: a scene of 200 objects needs about" none tm -- "$tabletop" crowd200.json --max-memory-mb 64 --out tm
      expect "tabletop scene above --max-memory-mb names the flag" 1 "above --max-memory-mb 64 (raise it" none tm -- "$tabletop" crowd200.json --max-memory-mb 64 --out tm
    fi
    # Point clouds (--cloud, when the kit has the perception front end): corrupt files.
    printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n' > probe.ply
    if [[ "$("$tabletop" --cloud probe.ply --out tprobe 2>&1)" == *"without PCL"* ]]; then
      skip "tabletop --cloud cases" "tabletop built without the perception front end"
    else
      expect "cloud: /dev/zero" 1 "/dev/zero: expected a regular file" none tc -- "$tabletop" --cloud /dev/zero --out tc
      mkfifo pipe.ply
      expect "cloud: a pipe" 1 "pipe.ply: expected a regular file" none tc -- "$tabletop" --cloud pipe.ply --out tc
      printf 'PLY\nformat ascii 1.0\n' > notply.ply
      expect "cloud: not a PLY file" 1 "notply.ply: header line 1: not a PLY file" none tc -- "$tabletop" --cloud notply.ply --out tc
      { printf 'ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float y\nproperty float z\nend_header\n'; head -c 120 /dev/zero; } > trunc.ply
      expect "cloud: truncated binary PLY" 1 "trunc.ply: header line 3: 100 vertex elements of at least 12 bytes need 1200 bytes, the file has 120 left (truncated?)" none tc -- "$tabletop" --cloud trunc.ply --out tc
      printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n' > huge.ply
      expect "cloud: huge element count" 1 "huge.ply: header line 3: expected \"element <name> <count>\" with a count of at most the file size" none tc -- "$tabletop" --cloud huge.ply --out tc
      printf 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 x 6\n' > word.ply
      expect "cloud: a word in an ASCII PLY" 1 "word.ply: line 9: vertex 1: \"x\" is not a number" none tc -- "$tabletop" --cloud word.ply --out tc
      printf 'VERSION 0.7\nFIELDS y z\nSIZE 4 4\nTYPE F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2\n' > nox.pcd
      expect "cloud: PCD with no x field" 1 "nox.pcd: header line 2: no field \"x\"" none tc -- "$tabletop" --cloud nox.pcd --out tc
      { printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 10\nHEIGHT 1\nPOINTS 10\nDATA binary_compressed\n'; printf '\x10\x00\x00\x00\x78\x00\x00\x00'; } > packed.pcd
      expect "cloud: truncated compressed PCD" 1 "packed.pcd: byte 98: compressed size 16 exceeds the 0 bytes that follow (truncated?)" none tc -- "$tabletop" --cloud packed.pcd --out tc
      python3 -c "
import random
random.seed(1)
print('ply\nformat ascii 1.0\nelement vertex 20000\nproperty float x\nproperty float y\nproperty float z\nend_header')
for i in range(20000): print(random.random(), random.random(), random.random())" > cloud20k.ply
      expect "tabletop cloud above --max-memory-mb" 1 "cloud20k.ply: a cloud of 20000 points needs about" none tc -- "$tabletop" --cloud cloud20k.ply --max-memory-mb 40 --out tc
      # SIGINT 2 s into the clustering of a dense cloud (100,000 points in a 6 cm box above a
      # table: about 5 s of radius searches): exit 130 within 3 s, the previous folder intact.
      python3 -c "
import random
random.seed(3)
print('ply\nformat ascii 1.0\nelement vertex 150000\nproperty float x\nproperty float y\nproperty float z\nend_header')
for i in range(50000): print('%.4f %.4f %.4f' % (random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), random.gauss(0, 0.001)))
for i in range(100000): print('%.4f %.4f %.4f' % (random.uniform(-0.03, 0.03), random.uniform(-0.03, 0.03), random.uniform(0.02, 0.08)))" > dense.ply
      "$tabletop" scene.json --iterations 20 --quiet --out tdense >/dev/null 2>&1
      expect "tabletop SIGINT while clustering a cloud" 130 "interrupted by SIGINT before a state existed" intact tdense -- \
        timeout -s KILL 5 timeout --foreground --preserve-status -s INT 2 "$tabletop" --cloud dense.ply --out tdense
    fi
  else
    skip "tabletop cases" "no $tabletop (kit not built)"
  fi
  if [ -x "$indoor" ]; then
    cp "$src/examples/indoor/sim_office.pgm" .
    sed -E 's/^resolution:.*/resolution: 1e-300/' "$src/examples/indoor/sim_office.yaml" > tiny.yaml
    sed -E 's/^resolution:.*/resolution: 1e300/' "$src/examples/indoor/sim_office.yaml" > huge.yaml
    expect "map YAML resolution: 1e-300" 1 "tiny.yaml:2: " none m1 -- "$indoor" tiny.yaml --out m1
    expect "map YAML resolution: 1e-300 message" 1 "outside the plausible range" none m1 -- "$indoor" tiny.yaml --out m1
    expect "map YAML resolution: 1e300" 1 "huge.yaml:2: " none m1 -- "$indoor" huge.yaml --out m1
    expect "--resolution 1e300" 1 "outside the plausible range" none m1 -- "$indoor" sim_office.pgm --resolution 1e300 --out m1
    # A message that names its file is printed as it is: no "indoor: error: map.pgm: error:".
    { printf 'P5\n10 10\n255\n'; head -c 30 sim_office.pgm; } > trunc.pgm
    expect "indoor: truncated PGM" 1 "^trunc.pgm: error: PGM (P5) pixel data is truncated: header says 10x10 = 100 bytes, file has 30" none m1 -- "$indoor" trunc.pgm --out m1
    cp "$src/examples/indoor/sim_office.yaml" office.yaml
    expect "indoor SIGTERM mid-run" 143 "interrupted by SIGTERM" complete iterm -- timeout --foreground --preserve-status -s TERM 5 "$indoor" office.yaml --iterations 100000000000 --out iterm
    [ -d iterm ] && manifest_complete iterm "indoor: every file listed"
    # Large maps: refused above --max-memory-mb with the estimate (a 600 x 400 map, limit 40 MB).
    expect "indoor map above --max-memory-mb" 1 "sim_office.pgm: a 600 x 400 map needs about" none mm -- "$indoor" sim_office.pgm --max-memory-mb 40 --out mm
    expect "indoor map above --max-memory-mb names the flag" 1 "above --max-memory-mb 40 (raise it to run anyway)" none mm -- "$indoor" sim_office.pgm --max-memory-mb 40 --out mm
  else
    skip "indoor cases" "no $indoor (kit not built)"
  fi
}
