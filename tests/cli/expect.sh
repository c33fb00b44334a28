# What the CLI test scripts share (sourced): a scratch directory removed at exit, a failure
# count, and `expect CODE PATTERN -- command…`, which runs the command and checks its exit
# code and that its output or errors contain PATTERN.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

expect() {
  local code=$1 pattern=$2
  shift 3
  "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [ "$got" -ne "$code" ]; then
    fail "'$*' exited $got, expected $code"; cat "$work/err"
  elif ! grep -qF -- "$pattern" "$work/out" "$work/err"; then
    fail "'$*' did not print: $pattern"; cat "$work/out" "$work/err"
  else
    echo "ok: $* -> $code"
  fi
}
