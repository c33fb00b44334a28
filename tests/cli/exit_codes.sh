#!/usr/bin/env bash
# The command line's contract: exit 0 on success, 2 on bad input (message names file, line,
# key), 3 on numerical failure (message names time, step, body, point), and complete files.
set -u
pellicle=$1
here=$2
cases=$3
. "$(dirname "$0")/expect.sh"

# Success: check and a short run of the default case.
expect 0 "check     ok" -- "$pellicle" check "$cases/two_disks.toml"
expect 0 "results   $work/default" -- "$pellicle" run --quiet --out "$work/default" --set solver.end_time=0.05
for f in history.csv summary.json points.pvd points_000000.vtu; do
  [ -s "$work/default/$f" ] || fail "$f missing after a run"
done
[ "$(cat "$work/default/status")" = completed ] || fail "status not completed"

# A run owns its directory: a used one is refused; --overwrite replaces Pellicle's files only
# (the first run's extra snapshots go, a user's file stays).
expect 2 "default is not empty (another run's results, completed): give another --out, or --overwrite" -- \
  "$pellicle" run --quiet --out "$work/default" --set solver.end_time=0.05
touch "$work/default/notes.txt"
expect 0 "results" -- "$pellicle" run --quiet --overwrite --out "$work/default" \
  --set solver.end_time=0.05 --set output.snapshot_interval=0.05
[ -e "$work/default/notes.txt" ] || fail "--overwrite removed a user's file"
[ "$(ls "$work/default" | grep -c '\.vtu$')" -eq 2 ] ||
  { echo "FAIL: --overwrite left the first run's snapshots"; ls "$work/default"; failures=$((failures + 1)); }

# Bad input: exit 2, nothing run, message with file:line:col and key.
expect 2 "bad_key.toml:11:1: solver.end_tme: unknown key" -- "$pellicle" check "$here/bad_key.toml"
expect 2 "bad_key.toml:11:1: solver.end_tme: unknown key" -- "$pellicle" run --out "$work/bad" "$here/bad_key.toml"
[ -e "$work/bad" ] && fail "bad input created output"
expect 2 "--set solver.cfl=2: solver.cfl: expected a number in (0, 1], found the integer 2" -- \
  "$pellicle" check "$cases/two_disks.toml" --set solver.cfl=2
expect 2 "cannot open the case file" -- "$pellicle" run "$work/missing.toml"
touch "$work/a-file"
expect 2 "--out: cannot create $work/a-file/sub: Not a directory" -- "$pellicle" run --quiet --out "$work/a-file/sub"
expect 2 "not expected: --no-such-flag" -- "$pellicle" run --no-such-flag
expect 2 "--set body[0].internal_energy=-2.5: body[0].internal_energy: expected a number >= 0" -- \
  "$pellicle" check "$cases/sod_shock_tube.toml" --set 'body[0].internal_energy=-2.5'
expect 0 "warning   body 'gas' is a fluid moved by FLIP" -- "$pellicle" check "$cases/gas_expansion.toml"

# A full disk is an output error: exit 1, naming the file or directory that could not be
# written, never "a problem in the input" (the input was fine). Simulated without root by a
# file size limit: with SIGXFSZ ignored, a write past it fails with EFBIG, as on a full disk.
# The command's messages go through a pipe, which the limit spares.
no_room() {  # no_room KIB DIR [ARGS…]: a short run whose files cannot grow past KIB KiB
  local kib=$1 out=$2
  shift 2
  (trap '' XFSZ; ulimit -f "$kib"; exec "$pellicle" run --quiet --threads 1 --out "$out" "$@") \
    2>&1 >/dev/null
}
expect_output_error() {  # expect_output_error LABEL CODE MESSAGES PATTERN
  local label=$1 code=$2 messages=$3 pattern=$4
  if [ "$code" -ne 1 ]; then
    echo "FAIL: $label exited $code, expected 1"; echo "$messages"; failures=$((failures + 1))
  elif ! grep -qF -- "$pattern" <<<"$messages"; then
    echo "FAIL: $label did not print: $pattern"; echo "$messages"; failures=$((failures + 1))
  elif grep -qi "input" <<<"$messages"; then
    echo "FAIL: $label blamed the input"; echo "$messages"; failures=$((failures + 1))
  else
    echo "ok: $label -> 1"
  fi
}
messages=$(no_room 0 "$work/full" "$cases/two_disks.toml" --set solver.end_time=0.05)
expect_output_error "full disk at the first write" $? "$messages" "cannot write $work/full/"
messages=$(no_room 0 "$work/full-surface" "$cases/surface_cdr_sphere.toml" \
  --set surface.smoothing_length=0.4 --set solver.end_time=0.01)
expect_output_error "full disk at a surface run's first write" $? "$messages" \
  "cannot write $work/full-surface/"
# Room for the status and the history's first rows, not for the first snapshot.
messages=$(no_room 8 "$work/snapshot" "$cases/two_disks.toml" --set solver.end_time=0.05)
expect_output_error "full disk at the first snapshot" $? "$messages" \
  "cannot write $work/snapshot/points_000000.vtu"
ls "$work/snapshot" | grep -q '\.part$' && fail "temporary file left"
grep -qx failed "$work/snapshot/status" || { echo "FAIL: status after an output error: $(cat "$work/snapshot/status")"; failures=$((failures + 1)); }
# A file system with no room even for the output directory: a tmpfs with no inode left
# refuses new directories (ENOSPC). Where the system lets a user mount one in a namespace of
# its own; elsewhere this check is skipped.
mkdir "$work/tiny"
full_tmpfs() {  # full_tmpfs DIR COMMAND…: COMMAND with a full tmpfs mounted on DIR
  unshare --user --map-root-user --mount sh -c \
    'mount -t tmpfs -o size=64k,nr_inodes=2 tmpfs "$1" && touch "$1/filler" || exit 99
     shift; exec "$@"' sh "$@"
}
if full_tmpfs "$work/tiny" true 2>/dev/null; then
  messages=$(full_tmpfs "$work/tiny" "$pellicle" run --quiet --threads 1 --out "$work/tiny/out" \
    "$cases/two_disks.toml" --set solver.end_time=0.05 2>&1 >/dev/null)
  expect_output_error "full disk at the output directory" $? "$messages" \
    "cannot create $work/tiny/out: No space left on device"
else
  echo "skip: cannot mount a full file system in a user namespace here"
fi

# Gas expanding: a warning once the points are more than a cell apart along the stretch
# (symmetric rarefaction), exit 3 naming the point when it expands into vacuum.
rarefaction=(--set body[0].density=1.0 --set body[0].internal_energy=1.0 --set body[1].density=1.0
  --set body[1].internal_energy=1.0 --set solver.end_time=0.15)
expect 0 "body 'high' has thinned to fewer than one point per cell along its stretch" -- \
  "$pellicle" run --quiet --out "$work/rarefaction" "$cases/sod_shock_tube.toml" "${rarefaction[@]}" \
  --set 'body[0].velocity=[-1.0, 0.0]' --set 'body[1].velocity=[1.0, 0.0]'
expect 3 "the gas has expanded into vacuum beyond what its points represent" -- \
  "$pellicle" run --quiet --out "$work/vacuum" "$cases/sod_shock_tube.toml" "${rarefaction[@]}" \
  --set 'body[0].velocity=[-2.0, 0.0]' --set 'body[1].velocity=[2.0, 0.0]'

# Numerical failure: exit 3 with time, step, body, point; history and snapshots complete.
expect 3 "body 'block', point" -- "$pellicle" run --quiet --out "$work/cfl" "$here/unstable.toml"
grep -q "CFL number" "$work/err" || fail "CFL failure not named"
expect 3 "body 'block', point" -- "$pellicle" run --quiet --out "$work/leave" "$here/leaves_grid.toml"
grep -q '"status": "failed: numerical failure' "$work/leave/summary.json" ||
  fail "summary.json does not record the failure"
[ "$(cat "$work/leave/status")" = failed ] || fail "status not failed"
ls "$work/leave" | grep -q '\.part$' && fail "temporary file left"

# SIGTERM: the run stops after its step, writes checkpoint.h5 and an "interrupted" summary,
# exits 143; the checkpoint restarts (with a longer end time) and a changed key is refused.
"$pellicle" run --quiet --threads 1 --out "$work/term" "$cases/two_disks.toml" \
  --set solver.end_time=1000 >/dev/null 2>"$work/term.err" &
run=$!
for _ in $(seq 100); do [ -f "$work/term/history.csv" ] && break; sleep 0.1; done
sleep 0.5
kill -TERM "$run"
wait "$run"; code=$?
[ "$code" -eq 143 ] || fail "SIGTERM exit code $code, expected 143"
[ -f "$work/term/checkpoint.h5" ] || fail "no checkpoint after SIGTERM"
grep -q '"status": "interrupted"' "$work/term/summary.json" ||
  fail "summary.json does not say interrupted"
[ "$(cat "$work/term/status")" = interrupted ] || fail "status not interrupted"
stopped=$(grep -o '"time": [0-9.e+-]*' "$work/term/summary.json" | awk '{print $2}')
expect 0 "results" -- "$pellicle" run --quiet --threads 1 --out "$work/resumed" \
  "$cases/two_disks.toml" --set "solver.end_time=$(awk -v t="$stopped" 'BEGIN{print t + 0.002}')" \
  --restart "$work/term/checkpoint.h5"
expect 2 "grid.cell: a restart cannot change this key" -- "$pellicle" run --quiet \
  --out "$work/refused" "$cases/two_disks.toml" --set grid.cell=0.05 --restart "$work/term/checkpoint.h5"
expect 2 "not an HDF5 file" -- "$pellicle" run --quiet --out "$work/refused" \
  "$cases/two_disks.toml" --restart "$work/term/summary.json"

# pellicle normals: a circle with exact normals; errors reported, bad files rejected.
/usr/bin/env python3 - "$work/circle.csv" <<'PY' 2>/dev/null || awk 'BEGIN{pi=atan2(0,-1); print "x,y,nx,ny"; for(k=0;k<100;k++){a=2*pi*k/100; printf "%.9f,%.9f,%.9f,%.9f\n", 5+2*cos(a), 5+2*sin(a), cos(a), sin(a)}}' > "$work/circle.csv"
import math, sys
with open(sys.argv[1], "w") as f:
    f.write("x,y,nx,ny\n")
    for k in range(100):
        a = 2 * math.pi * k / 100
        f.write("%.9f,%.9f,%.9f,%.9f\n" % (5 + 2 * math.cos(a), 5 + 2 * math.sin(a), math.cos(a), math.sin(a)))
PY
expect 0 "error     max" -- "$pellicle" normals --points "$work/circle.csv" --cell 0.25 --method pca --out "$work/n.csv"
[ "$(wc -l < "$work/n.csv")" -eq 101 ] || fail "normals output has the wrong length"
# Orientation: outward from the centroid, or away from a given inside point, matches the
# circle's exact (outward) normals; the report counts the reversed ones.
expect 0 "side      0 of 100 normals (0 %) face opposite to the exact normal (--orient outward)" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell 0.25 --orient outward --out "$work/n.csv"
expect 0 "side      0 of 100 normals (0 %) face opposite to the exact normal (--inside)" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell 0.25 --method pca --inside 5,5 --out "$work/n.csv"
expect 2 "--inside: expected 2 numbers for these 2D points" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell 0.25 --inside 5,5,1 --out "$work/n.csv"
printf 'x,y\n1,2\n1,2,3\n' > "$work/ragged.csv"
expect 2 "ragged.csv:3:1: --points: row has 3 columns, unlike the rows before it" -- \
  "$pellicle" normals --points "$work/ragged.csv" --cell 1 --out "$work/r.csv"
expect 2 "expected a connectivity-free estimator" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell 1 --method connectivity --out "$work/r.csv"

# Coordinates and options that cannot be numbered as cells: refused with row and column.
for method in isosurface-hybrid mass-matrix pca; do
  printf 'x,y\n0,0\nnan,1\n' > "$work/nan.csv"
  expect 2 "nan.csv:3:1: --points: column 1 (x): expected a finite number, found nan" -- \
    "$pellicle" normals --points "$work/nan.csv" --cell 0.1 --method "$method" --out "$work/r.csv"
  printf 'x,y\n0,0\n1,1e300\n' > "$work/far.csv"
  expect 2 "far.csv:3:1: --points: column 2 (y = 1e+300) lies 1e+301 cells from the origin" -- \
    "$pellicle" normals --points "$work/far.csv" --cell 0.1 --method "$method" --out "$work/r.csv"
done
expect 2 "command line: --cell: expected a finite cell size, found nan" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell nan --out "$work/r.csv"
expect 2 "command line: --origin: expected finite numbers, found nan" -- \
  "$pellicle" normals --points "$work/circle.csv" --cell 0.1 --origin nan,0 --out "$work/r.csv"

# What a newcomer asks the program.
expect 0 "pellicle 0." -- "$pellicle" --version
expect 0 "Subcommands:" -- "$pellicle" help
expect 0 "cases/airbag_demo.toml" -- "$pellicle" list cases
expect 0 "isosurface-hybrid" -- "$pellicle" list estimators
expect 0 "dogbone" -- "$pellicle" list problems
expect 0 "points, mass 126.094 kg/m of depth" -- "$pellicle" check "$cases/two_disks.toml"
# Every case-file key the user guide documents, or one section's; unknown words are refused.
expect 0 "solver.end_time" -- "$pellicle" list keys
expect 0 "body.membrane.thickness" -- "$pellicle" list keys body.membrane
expect 2 "list keys: no key under \"solvr\" in the user guide; sections: case, grid, solver" -- \
  "$pellicle" list keys solvr
expect 2 "what: expected cases, problems, estimators, kernels, materials or keys, found 'bogus'" -- \
  "$pellicle" list bogus
expect 2 "list cases: takes no further word" -- "$pellicle" list cases solver

# Runs that would never end are refused before they start.
expect 2 "solver.cfl: the CFL step is 0 s" -- "$pellicle" check "$cases/two_disks.toml" \
  --set 'body[0].velocity=[1e300, 0]'
expect 2 "solver.dt: a time step of 1e-300 s takes 5e+298 steps to reach end_time = 0.05" -- \
  "$pellicle" check "$cases/fsi_quarter_circle.toml" --set solver.dt=1e-300

# Problems too large for the machine are refused from the case, before anything is built.
expect 2 "body[1]: the problem needs about" -- "$pellicle" check "$cases/fsi_quarter_circle.toml" \
  --set grid.cell=1e-4 --set solver.dt=1e-9
expect 2 "grid.cell: expected at most 1e+07 cells on an axis" -- "$pellicle" check \
  "$cases/two_disks.toml" --set 'grid.upper=[2147483648.0, 1.0]' --set grid.cell=1.0
expect 0 "warning: body 'lower-disk': part of its region lies outside the grid" -- \
  "$pellicle" check "$cases/two_disks.toml" --set 'body[0].region.center=[0.05, 0.5]'
# A membrane is estimated from its length or area and its spacing (or its points) before it
# is sampled: a drum at spacing 10⁻⁵ (3.8·10¹⁰ points, 58 TB) is refused at once, naming the key.
expect 2 "body[0].membrane.spacing: about 3.8e+10 points (area 3.8 at spacing 1e-05)" -- \
  timeout 5 "$pellicle" check "$cases/drum.toml" --set 'body[0].membrane.spacing=1e-5'
# Surface cases too: the cloud is estimated from the shape's area and its spacing before it is
# sampled, and refused at once (a sphere of radius 10⁶ at h = 10⁻³; the unit sphere at
# h = 3·10⁻⁴, which fits the indices but no machine's memory). `check` prints the estimate.
sed -e 's/radius = 1.0 }/radius = 1e6 }/' -e 's/^smoothing_length = 0.1 /smoothing_length = 1e-3/' \
  "$cases/surface_cdr_sphere.toml" > "$work/huge_sphere.toml"
expect 2 "huge_sphere.toml:17:20: surface.smoothing_length: the initial cloud would hold about 7.48e+19 points" -- \
  timeout 2 "$pellicle" check "$work/huge_sphere.toml"
expect 2 "more than the 2.15e+09 a cloud can index" -- timeout 2 "$pellicle" run --quiet \
  --out "$work/huge" "$work/huge_sphere.toml"
[ -e "$work/huge" ] && fail "an oversized surface case created output"
expect 2 "surface.smoothing_length: the problem needs about 3.41e+03 GB" -- \
  timeout 2 "$pellicle" check "$cases/surface_cdr_sphere.toml" --set surface.smoothing_length=3e-4
grep -qF "this machine has available" "$work/err" ||
  fail "the surface memory check does not name the available memory"
expect 0 "(4.0 kB a point; the shape's area gave 7483 points before sampling)" -- \
  "$pellicle" check "$cases/surface_cdr_sphere.toml"

# Thread counts this machine cannot honour; case files that are not files.
expect 2 "--threads: expected a whole number from 1 to" -- "$pellicle" run --threads 0
expect 2 "--threads: expected a whole number from 1 to" -- "$pellicle" run --threads 100000
expect 2 "expected a case file, found a directory" -- "$pellicle" check "$work"
expect 2 "expected a case file, found a pipe, socket or device" -- "$pellicle" check /dev/zero
mkfifo "$work/fifo.toml"
expect 2 "expected a case file, found a pipe, socket or device" -- timeout 10 "$pellicle" check "$work/fifo.toml"

# The benchmark: an unknown case is refused with the known ones; every case reports its
# throughput and memory per point in JSON.
expect 2 "no benchmark named 'disks' (known: two-disks," -- "$pellicle" bench --case disks
expect 0 '"bytes_per_point"' -- "$pellicle" bench --json --points 1000 --steps 1 --threads 1
for c in two-disks two-disks-contact gas-box gas-in-membrane two-spheres-3d two-spheres-3d-musl \
  two-spheres-3d-flip; do
  grep -q "\"case\": \"$c\".*\"state_bytes_per_point\": [0-9].*\"instruction_set\": \"[^\"]" \
    "$work/out" || fail "pellicle bench --json has no result for $c"
done

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
