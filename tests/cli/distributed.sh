#!/usr/bin/env bash
# `mpirun -np N pellicle run`: exit codes, the files of a distributed run (one history and
# summary, a .vtu piece per rank joined by a .pvtu that declares the pieces' arrays; grid
# pieces; probes; checkpoints continued on other rank counts), and what it refuses. The
# agreement of the numbers with one process is tests/mpi/.
set -u
mpirun=$1
pellicle=$2
cases=$3
. "$(dirname "$0")/expect.sh"

run2=("$mpirun" -np 2 --oversubscribe "$pellicle" run --quiet)
short=(--set grid.cell=0.025 --set solver.end_time=0.3 --set output.snapshot_interval=0.1)

expect 0 "results   $work/two" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/two" "${short[@]}"
[ "$(cat "$work/two/status")" = completed ] || fail "status not completed"
grep -q '"ranks": 2' "$work/two/summary.json" || fail "summary.json lacks \"ranks\": 2"
grep -q '"threads": ' "$work/two/summary.json" || fail "summary.json lacks threads"
grep -q '"distributed.halo_bytes_per_step": ' "$work/two/summary.json" || fail "no halo figures"
# The same points as one process (every point on exactly one rank).
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/one" "${short[@]}"
points() { grep -m1 '"points"' "$1/summary.json" | tr -dc 0-9; }
[ "$(points "$work/two")" = "$(points "$work/one")" ] || fail "point counts differ from one process"
[ "$(head -1 "$work/two/history.csv")" = "$(head -1 "$work/one/history.csv")" ] ||
  fail "history columns differ from one process"
[ "$(wc -l <"$work/two/history.csv")" = "$(wc -l <"$work/one/history.csv")" ] ||
  fail "history rows differ from one process"
# Snapshots: the series lists .pvtu files; each joins both pieces and declares their arrays.
grep -q 'file="points_000003.pvtu"' "$work/two/points.pvd" || fail "points.pvd lacks the last .pvtu"
for s in 000000 000003; do
  pvtu="$work/two/points_$s.pvtu"
  for r in 0000 0001; do
    grep -q "<Piece Source=\"points_${s}_r$r.vtu\"/>" "$pvtu" || fail "$pvtu lacks piece r$r"
    piece="$work/two/points_${s}_r$r.vtu"
    [ -s "$piece" ] || fail "$piece missing"
    declared=$(sed -n '/<PPointData/,/<\/PPointData>/p' "$pvtu" | grep -o 'Name="[^"]*" NumberOfComponents="[0-9]*"')
    written=$(sed -n '/<PointData/,/<\/PointData>/p' "$piece" | grep -o 'Name="[^"]*" NumberOfComponents="[0-9]*"')
    [ -n "$declared" ] && [ "$declared" = "$written" ] || fail "$pvtu declares other arrays than $piece"
  done
done

# Continuing on two ranks from a one-process checkpoint: the last row of the history as one
# process continues it (time and step exactly, total energy to round-off).
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/first" \
  "${short[@]}" --checkpoint-interval 0.15
more=(--set grid.cell=0.025 --set solver.end_time=0.6 --restart "$work/first/checkpoint.h5")
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/on1" "${more[@]}"
expect 0 "results" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/on2" "${more[@]}"
tail -1 "$work/on1/history.csv" >"$work/last1"
tail -1 "$work/on2/history.csv" >"$work/last2"
awk -F, 'NR == FNR { t = $1; s = $2; e = $8; next }
         { exit !($1 == t && $2 == s && ($8 - e) ^ 2 <= (1e-9 * e) ^ 2) }' \
  "$work/last1" "$work/last2" || fail "a restart on two ranks ends elsewhere than on one"

# A checkpoint written on three ranks, whose outer pieces hold no points of one disk each,
# continues on one, two and three ranks to the same last row (each rank reads only the pieces
# whose boxes meet its patch).
run3=("$mpirun" -np 3 --oversubscribe "$pellicle" run --quiet)
expect 0 "results" -- "${run3[@]}" "$cases/two_disks.toml" --out "$work/t3" "${short[@]}" \
  --checkpoint-interval 0.15
more3=(--set grid.cell=0.025 --set solver.end_time=0.6 --restart "$work/t3/checkpoint.h5")
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/t3on1" "${more3[@]}"
expect 0 "results" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/t3on2" "${more3[@]}"
expect 0 "results" -- "${run3[@]}" "$cases/two_disks.toml" --out "$work/t3on3" "${more3[@]}"
# The index holds the box around each piece's points of each body (three pieces: six rows of
# corners), so that those ranks opened only the pieces whose boxes meet their patches.
for b in 0 1; do
  h5dump -d "/bodies/body_$b/boxes" "$work/t3/checkpoint.h5" | grep -q 'SIMPLE { ( 6, 2 )' ||
    fail "the three-rank checkpoint's index lacks the pieces' boxes of body $b"
done
# A body the changed case adds starts from its case state, the others from the checkpoint.
{
  cat "$cases/two_disks.toml"
  printf '\n[[body]]\nname = "third-disk"\nmaterial = "elastic"\npoints_per_cell = 2\n'
  printf 'region = { shape = "disk", center = [0.8, 0.2], radius = 0.1 }\n'
} >"$work/three_disks.toml"
expect 0 "body 'third-disk' is new" -- "${run2[@]}" "$work/three_disks.toml" --out "$work/t3new" \
  "${more3[@]}"

# A checkpoint written on two ranks, after the disks met under contact-release (whose node
# states it holds), continues on one and on three ranks as one process's own checkpoint does:
# time and step exactly, every column of the last row to round-off.
rel=(--set grid.cell=0.025 --set 'contact={model="release", criterion="both"}')
to17=(--set solver.end_time=1.7 --checkpoint-interval 1.7)
to22=(--set solver.end_time=2.2)
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/c1" "${rel[@]}" "${to17[@]}"
expect 0 "results" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/c2" "${rel[@]}" "${to17[@]}"
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/c1on1" "${rel[@]}" \
  "${to22[@]}" --restart "$work/c1/checkpoint.h5"
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/c2on1" "${rel[@]}" \
  "${to22[@]}" --restart "$work/c2/checkpoint.h5"
expect 0 "results" -- "$mpirun" -np 3 --oversubscribe "$pellicle" run --quiet "$cases/two_disks.toml" \
  --out "$work/c2on3" "${rel[@]}" "${to22[@]}" --restart "$work/c2/checkpoint.h5"
same_last_row() {
  paste -d, <(tail -1 "$1/history.csv") <(tail -1 "$2/history.csv") |
    awk -F, '{ n = NF / 2; if ($1 != $(1 + n) || $2 != $(2 + n)) exit 1
               for (i = 3; i <= n; ++i) if (($i - $(i + n)) ^ 2 > (1e-9 * $i) ^ 2 + 1e-24) exit 1 }'
}
same_last_row "$work/t3on1" "$work/t3on2" || fail "a three-rank checkpoint continues elsewhere on two"
same_last_row "$work/t3on1" "$work/t3on3" || fail "a three-rank checkpoint continues elsewhere on three"
same_last_row "$work/c1on1" "$work/c2on1" || fail "a two-rank checkpoint continues elsewhere on one"
same_last_row "$work/c1on1" "$work/c2on3" || fail "a two-rank checkpoint continues elsewhere on three"
grep -q "contact_x" "$work/c2on3/history.csv" || fail "the contact run has no contact columns"
# Each rank wrote its own piece of that checkpoint; a piece missing, or left from another
# checkpoint, is refused by name, on one process and on two ranks (where rank 0 checks them).
for r in 0000 0001; do
  [ -s "$work/c2/checkpoint_r$r.h5" ] || fail "checkpoint piece r$r missing"
done
[ ! -e "$work/c2/checkpoint_r0002.h5" ] || fail "a third checkpoint piece from two ranks"
mv "$work/c2/checkpoint_r0001.h5" "$work/c2/kept.h5"
expect 2 "checkpoint_r0001.h5" -- "$pellicle" run --quiet "$cases/two_disks.toml" \
  --out "$work/nopiece" "${rel[@]}" "${to22[@]}" --restart "$work/c2/checkpoint.h5"
expect 2 "checkpoint_r0001.h5" -- "${run2[@]}" "$cases/two_disks.toml" \
  --out "$work/nopiece2" "${rel[@]}" "${to22[@]}" --restart "$work/c2/checkpoint.h5"
cp "$work/first/checkpoint.h5" "$work/c2/checkpoint_r0001.h5"
expect 2 "not a piece of this checkpoint" -- "$pellicle" run --quiet "$cases/two_disks.toml" \
  --out "$work/badpiece" "${rel[@]}" "${to22[@]}" --restart "$work/c2/checkpoint.h5"
mv "$work/c2/kept.h5" "$work/c2/checkpoint_r0001.h5"
expect 2 "continue from $work/c2/checkpoint.h5" -- "$pellicle" run --quiet "$cases/two_disks.toml" \
  --out "$work/apiece" "${rel[@]}" "${to22[@]}" --restart "$work/c2/checkpoint_r0000.h5"

# Probes of points that migrate between the ranks (the pendulum's end mass and angle): the
# last row as one process writes it, to round-off.
swing=(--set solver.end_time=0.4 --set output.snapshot_interval=0.4)
expect 0 "results" -- "$pellicle" run --quiet "$cases/pendulum.toml" --out "$work/p1" "${swing[@]}"
expect 0 "results" -- "${run2[@]}" "$cases/pendulum.toml" --out "$work/p2" "${swing[@]}"
[ "$(head -1 "$work/p2/history.csv")" = "$(head -1 "$work/p1/history.csv")" ] ||
  fail "pendulum history columns differ from one process"
# Its string's frames came from a halo but the first, from the whole string gathered.
grep -q '"distributed.frames_gathered": 1,' "$work/p2/summary.json" ||
  fail "the pendulum's frames were gathered more than once"
grep -q '"distributed.frames_bytes_per_step": ' "$work/p2/summary.json" ||
  fail "no membrane frame figures"
paste -d, <(tail -1 "$work/p1/history.csv") <(tail -1 "$work/p2/history.csv") |
  awk -F, '{ n = NF / 2; for (i = n - 2; i <= n; ++i) if (($i - $(i + n)) ^ 2 > (1e-9 * $i) ^ 2) exit 1 }' ||
  fail "pendulum probes on two ranks differ from one process"

# Grid snapshots: a piece per rank joined by a .pvti; the pieces' nodes hold what one
# process's snapshot holds there.
grid=(--set output.grid_snapshots=true "${short[@]}")
expect 0 "results" -- "$pellicle" run --quiet "$cases/two_disks.toml" --out "$work/g1" "${grid[@]}"
expect 0 "results" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/g2" "${grid[@]}"
grep -q 'file="grid_000003.pvti"' "$work/g2/grid.pvd" || fail "grid.pvd lacks the last .pvti"
for r in 0000 0001; do
  grep -q "Source=\"grid_000003_r$r.vti\"" "$work/g2/grid_000003.pvti" || fail "no grid piece r$r"
done
/usr/bin/python3 "$(dirname "$0")/compare_grid_pieces.py" "$work/g1/grid_000003.vti" \
  "$work"/g2/grid_000003_r*.vti || fail "grid pieces differ from one process"

# Refused before anything runs (exit 2, named, reported once): a grid too small to split.
expect 2 "cannot split 4 x 4 cells among 2 ranks" -- \
  "${run2[@]}" "$cases/two_disks.toml" --out "$work/small" --set grid.cell=0.25
[ "$(grep -c 'cannot split' "$work/err")" = 1 ] || fail "refusal not reported once"
# A numerical failure stops every rank with exit 3 and says so in the status file.
expect 3 "CFL number c dt / h" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/fail" \
  --set solver.cfl=0.9 --set solver.cfl_limit=0.1
grep -q '^failed' "$work/fail/status" || fail "status of a failed distributed run is not 'failed'"
# A failing point is named as one process names it (its index in the body as built).
unstable=(--set solver.dt=0.01 --set solver.cfl_limit=1000)
expect 3 "body 'left-bar', point 16: the point left the grid domain" -- \
  "$pellicle" run --quiet "$cases/two_bars_stick.toml" --out "$work/f1" "${unstable[@]}"
expect 3 "body 'left-bar', point 16: the point left the grid domain" -- \
  "${run2[@]}" "$cases/two_bars_stick.toml" --out "$work/f2" "${unstable[@]}"

[ "$failures" -eq 0 ] && echo "all distributed CLI checks passed"
exit "$failures"
