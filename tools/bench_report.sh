#!/usr/bin/env bash
# Time the report build in a throw-away copy of the work tree (the real notebooks are never
# edited): (1) from a clean build/ with .venv present, (2) a second run with nothing changed,
# (3) after `touch` of one notebook (content hash: nothing to do), (4) after a real edit of one
# notebook (re-executes only that one, then re-exports). Prints a markdown table.
#   usage: tools/bench_report.sh            (run from the repository root, after `make venv tex`)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
PY=.venv/bin/python
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/root"
cp -r wmr notebooks tools "$tmp/root/"
[ -d figures ] && cp -r figures "$tmp/root/" || mkdir "$tmp/root/figures"
git -C "$tmp/root" init -q && git -C "$tmp/root" add -A >/dev/null && \
  git -C "$tmp/root" -c user.name=bench -c user.email=bench@localhost commit -qm bench
B="$PY $tmp/root/tools/build.py --root $tmp/root"
t() { local s e; s=$(date +%s.%N); "$@" > "$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }; e=$(date +%s.%N); \
      printf '%.2f' "$(echo "$e - $s" | bc)"; }
nb=$(ls "$tmp/root"/notebooks/*.ipynb | head -1)
t1=$(t $B report); grep -c '^\[execute\] .*ipynb (' "$tmp/log" > "$tmp/n1" || true
t2=$(t $B report)
touch "$nb"; t3=$(t $B report)
$PY - "$nb" <<'PY'
import sys, nbformat
nb = nbformat.read(sys.argv[1], as_version=4)
nb.cells.append(nbformat.v4.new_markdown_cell("Benchmark edit."))
nbformat.write(nb, sys.argv[1])
PY
t4=$(t $B report); n4=$(grep -c '^\[execute\] .*ipynb (' "$tmp/log" || true)
echo "| scenario | wall time (s) |"
echo "| --- | --- |"
echo "| clean build/ (venv present): $(cat "$tmp/n1") notebooks executed, figures, ledger, HTML + PDF | $t1 |"
echo "| second run, nothing changed | $t2 |"
echo "| \`touch\` one notebook (content unchanged) | $t3 |"
echo "| edit one notebook ($(basename "$nb")): $n4 re-executed, HTML + PDF re-exported | $t4 |"
