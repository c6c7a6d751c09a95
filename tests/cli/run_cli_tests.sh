#!/usr/bin/env bash
# End-to-end checks of the `flatfacet` command: outputs, determinism, exit codes and clear
# one-line errors that leave nothing behind. Needs $FLATFACET and $FF_SHARED_MESHES.
set -uo pipefail
bin=${FLATFACET:?}
meshes=${FF_SHARED_MESHES:?}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# expect_error CODE PATTERN ARGS...: exit code, one stderr line matching PATTERN, no labels file.
expect_error() {
  local code=$1 pattern=$2
  shift 2
  rm -f "$tmp/err.txt"
  "$bin" "$@" 2>"$tmp/err.txt" >/dev/null
  local got=$?
  local lines
  lines=$(wc -l <"$tmp/err.txt")
  if [ "$got" != "$code" ]; then bad "exit $got (want $code): $*"; cat "$tmp/err.txt"; return; fi
  if [ "$lines" != 1 ]; then bad "$lines stderr lines (want 1): $*"; cat "$tmp/err.txt"; return; fi
  if ! grep -qiE "$pattern" "$tmp/err.txt"; then bad "message '$(cat "$tmp/err.txt")' lacks /$pattern/: $*"; return; fi
  if [ -e "$tmp/never.txt" ]; then bad "an output was written despite the error: $*"; rm -f "$tmp/never.txt"; return; fi
  ok
}

# Labels for every shared mesh: one per input triangle, ids in [0, N), all N used.
for mesh in "$meshes"/*.off "$meshes"/*.obj; do
  name=$(basename "$mesh")
  if ! "$bin" cluster "$mesh" --panels 40 --seed 3 --labels "$tmp/$name.labels" --summary "$tmp/$name.json" 2>"$tmp/err.txt"; then
    bad "cluster $name failed: $(cat "$tmp/err.txt")"
    continue
  fi
  python3 - "$mesh" "$tmp/$name.labels" "$tmp/$name.json" <<'PY' && ok || bad "labels/summary check for $name"
import json, sys
mesh, labels_path, summary_path = sys.argv[1:]
labels = [int(x) for x in open(labels_path).read().split()]
summary = json.load(open(summary_path))
assert summary["clusters"] == 40, summary
assert summary["input_triangles"] == len(labels), (summary["input_triangles"], len(labels))
assert set(labels) == set(range(40)), sorted(set(labels))[:5]
for key in ("euclidean", "l2", "l21", "density", "total"):
    assert key in summary["energy"]
assert summary["iterations"] >= 1 and summary["timings_s"]["total"] > 0
PY
done

# Determinism: identical input, options and seed give an identical labels file.
m="$meshes/bunny.off"
"$bin" cluster "$m" --panels 64 --seed 9 --labels "$tmp/a.txt" && "$bin" cluster "$m" --panels 64 --seed 9 --labels "$tmp/b.txt"
cmp -s "$tmp/a.txt" "$tmp/b.txt" && ok || bad "same seed gave different labels"
"$bin" cluster "$m" --panels 64 --seed 10 --labels "$tmp/c.txt"
cmp -s "$tmp/a.txt" "$tmp/c.txt" && bad "different seeds gave identical labels" || ok
"$bin" cluster "$m" --panels 64 --seed 9 --seeding random --iterations 5 --no-teleport \
  --weights euclidean=0,l2=1,l21=0 --labels "$tmp/d.txt" && ok || bad "options run"

# Density file: per vertex; dense values in one half.
nv=$(awk 'NR==2{print $1}' "$m")
python3 -c "
import sys
lines=open('$m').read().split('\n')
n=int(lines[1].split()[0])
xs=[float(l.split()[0]) for l in lines[2:2+n]]
mid=sorted(xs)[n//2]
print('\n'.join('4' if x<mid else '1' for x in xs))" >"$tmp/density.txt"
"$bin" cluster "$m" --panels 50 --density "$tmp/density.txt" --labels "$tmp/e.txt" && ok || bad "density run"
# Per-triangle density works too.
nf=$(awk 'NR==2{print $2}' "$m")
python3 -c "print('\n'.join('3' if i % 2 else '1' for i in range($nf)))" >"$tmp/face_density.txt"
"$bin" cluster "$m" --panels 50 --density "$tmp/face_density.txt" --labels "$tmp/f.txt" && ok || bad "per-triangle density run"
# Zero iterations: the seeded clustering itself.
"$bin" cluster "$m" --panels 30 --iterations 0 --labels "$tmp/g.txt" --summary "$tmp/g.json" &&
  python3 -c "import json; d=json.load(open('$tmp/g.json')); assert d['iterations'] == 0 and d['clusters'] == 30" && ok ||
  bad "--iterations 0"
# An output that cannot be written: exit 2 and no other output left behind.
rm -f "$tmp/never.txt"
expect_error 2 "cannot write" cluster "$m" --panels 10 --labels "$tmp/never.txt" --summary "$tmp/no/such/dir/s.json"
echo "1 2 3" >"$tmp/short.txt"
expect_error 2 "density.*3 values.*$nv" cluster "$m" --panels 10 --density "$tmp/short.txt" --labels "$tmp/never.txt"

# Bad input: each gets exit 2 and one line naming the problem.
expect_error 2 "cannot open" cluster "$tmp/missing.obj" --panels 10 --labels "$tmp/never.txt"
head -c 3000 /dev/urandom >"$tmp/garbage.obj"
expect_error 2 "OBJ" cluster "$tmp/garbage.obj" --panels 10 --labels "$tmp/never.txt"
: >"$tmp/empty.off"
expect_error 2 "empty" cluster "$tmp/empty.off" --panels 10 --labels "$tmp/never.txt"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n' >"$tmp/badindex.obj"
expect_error 2 "range" cluster "$tmp/badindex.obj" --panels 1 --labels "$tmp/never.txt"
printf 'v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$tmp/nan.obj"
expect_error 2 "nan|finite" cluster "$tmp/nan.obj" --panels 1 --labels "$tmp/never.txt"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 2 3\nf 1 2 4\nf 1 2 5\n' >"$tmp/nonmanifold.obj"
expect_error 2 "non-manifold edge" cluster "$tmp/nonmanifold.obj" --panels 1 --labels "$tmp/never.txt"
expect_error 2 "panels.*triangles|triangles.*panels" cluster "$meshes/epcot.off" --panels 99999 --labels "$tmp/never.txt"
expect_error 2 "whole number" cluster "$meshes/epcot.off" --panels abc --labels "$tmp/never.txt"
expect_error 2 "unknown option" cluster "$meshes/epcot.off" --panels 5 --bogus 1 --labels "$tmp/never.txt"
expect_error 2 "required" cluster "$meshes/epcot.off" --labels "$tmp/never.txt"
expect_error 2 "weights" cluster "$meshes/epcot.off" --panels 5 --weights l3=1 --labels "$tmp/never.txt"
expect_error 2 "unknown command" frobnicate

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
