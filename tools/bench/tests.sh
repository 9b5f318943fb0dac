#!/usr/bin/env bash
# Time a warm `make test`: nothing changed since the last run, so every notebook, the report,
# the student edition and the lessons' grades are cached, and so are the results of tests/edition/
# (tools/testcache.py): the time is the library's tests (pytest, two workers), ruff and mypy. Runs
# `make test` once to warm up, then RUNS timed runs (default 2), then one with FRESH=1 (the
# edition's tests run too, as after any change), each with the load average read
# just before it (other users of the two cores slow it down) and the CPU time it used (user + sys
# of make and everything it started: on an idle 2-core machine the wall time is about half of it),
# the slowest tests of the last run, and its CPU seconds per test file (the plugin tools/pytest_cpu.py).
#   usage: tools/bench/tests.sh [RUNS]            (from the repository root)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
runs=${1:-2}
mkdir -p build
log=build/bench-test.log
load() { cut -d' ' -f1 /proc/loadavg; }
# the exit status is reported, not fatal: a failing check (a lint finding) takes the same time
status() { grep -E "^[0-9]+ (passed|failed)|passed in|^\[git\]|^make: \*\*\*" "$log" | tr '\n' ' ' | cut -c1-150; }
args="--durations=12 -p tools.pytest_cpu"  # the same in every run: the arguments are part of the key
t0=$(date +%s.%N)
make test PYTEST_ARGS="$args" > "$log" 2>&1 || true
printf '[bench] warm-up make test: %.1f s: %s\n' "$(echo "$(date +%s.%N) - $t0" | bc)" "$(status)"
echo "| run | warm make test, wall (s) | CPU, user + sys (s) | load before | result |"
echo "| --- | --- | --- | --- | --- |"
for i in $(seq "$runs") FRESH; do
  l=$(load)
  rm -rf build/cpu
  fresh=; [ "$i" = FRESH ] && fresh=1
  /usr/bin/time -f "%e %U %S" -o build/bench-test.time make test PYTEST_ARGS="$args" FRESH=$fresh \
    > "$log" 2>&1 || true
  read -r wall user sys < <(tail -1 build/bench-test.time)
  printf '| %s | %.1f | %.1f | %s | %s |\n' "$i" "$wall" "$(echo "$user + $sys" | bc)" "$l" "$(status)"
done
echo
echo "Slowest tests of the last run (FRESH=1: every test):"
sed -n '/slowest .* durations/,/^[(=]/p' "$log" | sed '1d;$d' | sed 's/^/    /'
echo
echo "CPU per test file of the last run (user + sys, with child processes; tools/pytest_cpu.py):"
.venv/bin/python -m tools.pytest_cpu build/cpu
echo
echo "The 25 tests that cost most CPU:"
.venv/bin/python -m tools.pytest_cpu build/cpu --tests 25
echo "Cores: $(nproc); load average now: $(cut -d' ' -f1-3 /proc/loadavg)"
