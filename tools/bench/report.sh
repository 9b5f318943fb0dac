#!/usr/bin/env bash
# Time the report build in a throw-away copy of the work tree (the real notebooks are never
# edited): (1) cold, from an empty build/ with .venv present, (2) a second run with nothing
# changed, (3) after `touch` of one notebook (content hash: nothing to do), (4) after a real edit
# of one notebook (re-executes only that one, then re-exports). Prints a markdown table, with
# the machine's load average before each run (other users of the cores slow it down).
#   usage: tools/bench/report.sh            (from the repository root, after `make venv tex`)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
PY=$PWD/.venv/bin/python
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/root"
cp -r wmr edition notebooks "$tmp/root/"
[ -d figures ] && cp -r figures "$tmp/root/" || mkdir "$tmp/root/figures"
git -C "$tmp/root" init -q && git -C "$tmp/root" add -A >/dev/null && \
  git -C "$tmp/root" -c user.name=bench -c user.email=bench@localhost commit -qm bench
B=(make --no-print-directory -C "$PWD" WMR_ROOT="$tmp/root" report)
load() { cut -d' ' -f1 /proc/loadavg; }
t() { local s e; s=$(date +%s.%N); "$@" > "$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }; \
      e=$(date +%s.%N); printf '%.1f' "$(echo "$e - $s" | bc)"; }
nb=$(ls "$tmp/root"/notebooks/[0-9]*.ipynb | head -1)
l1=$(load); t1=$(t "${B[@]}"); n1=$(grep -c '^\[execute\] .*ipynb (' "$tmp/log" || true)
steps=$(grep -E '^\[(execute|publish|assemble|html|pdf)\] ' "$tmp/log" || true)
l2=$(load); t2=$(t "${B[@]}")
touch "$nb"; l3=$(load); t3=$(t "${B[@]}")
"$PY" - "$nb" <<'PY'
import sys, nbformat
nb = nbformat.read(sys.argv[1], as_version=4)
nb.cells.append(nbformat.v4.new_markdown_cell("Benchmark edit."))
nbformat.write(nb, sys.argv[1])
PY
l4=$(load); t4=$(t "${B[@]}"); n4=$(grep -c '^\[execute\] .*ipynb (' "$tmp/log" || true)
echo "| scenario | wall time (s) | load before |"
echo "| --- | --- | --- |"
echo "| cold: empty build/, .venv present; $n1 notebooks executed, ledger, HTML + PDF | $t1 | $l1 |"
echo "| second run, nothing changed | $t2 | $l2 |"
echo "| \`touch\` one notebook (content unchanged) | $t3 | $l3 |"
echo "| edit one notebook ($(basename "$nb")): $n4 re-executed, HTML + PDF re-exported | $t4 | $l4 |"
echo
echo "Steps of the cold run:"
echo "$steps" | sed 's/^/    /'
echo "Cores: $(nproc); load average now: $(cut -d' ' -f1-3 /proc/loadavg)"
