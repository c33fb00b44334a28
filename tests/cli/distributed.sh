#!/usr/bin/env bash
# `mpirun -np N pellicle run`: exit codes, the files of a distributed run (one history and
# summary, a .vtu piece per rank joined by a .pvtu that declares the pieces' arrays), and what
# it refuses. The agreement of the numbers with one process is tests/mpi/.
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

# Refused before anything runs (exit 2, named, reported once).
expect 2 "a contact model cannot run on more than one rank yet" -- \
  "${run2[@]}" "$cases/ball_and_net.toml" --out "$work/net"
[ "$(grep -c 'cannot run on more than one rank' "$work/err")" = 1 ] || fail "refusal not reported once"
expect 2 "probes cannot be written by a run on more than one rank yet" -- \
  "${run2[@]}" "$cases/pendulum.toml" --out "$work/pendulum"
expect 2 "checkpoints cannot be written by a run on more than one rank yet" -- \
  "${run2[@]}" "$cases/two_disks.toml" --out "$work/cp" --checkpoint-interval 0.1
# A numerical failure stops every rank with exit 3 and says so in the status file.
expect 3 "CFL number c dt / h" -- "${run2[@]}" "$cases/two_disks.toml" --out "$work/fail" \
  --set solver.cfl=0.9 --set solver.cfl_limit=0.1
grep -q '^failed' "$work/fail/status" || fail "status of a failed distributed run is not 'failed'"

[ "$failures" -eq 0 ] && echo "all distributed CLI checks passed"
exit "$failures"
