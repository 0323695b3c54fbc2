#!/bin/sh
# Ctrl-C during a run leaves a valid, partial report that says it is partial (issue 6).
# usage: interrupt_test.sh VOXREF CHECK_RESULTS OUTDIR
# A run of two cases at once: one passes quickly, one hangs. Once the running snapshot of
# results.json holds the first, SIGINT is sent; the run must exit 130 (128 + SIGINT) with the
# first case's result, the hanging case listed as not run, no process left behind, and an
# index.html that says the report is partial.
set -u
voxref=$1 check=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$voxref" conform --runner-controls --filter 'sparsegrid.hard.level1,runner.control.hang' --jobs 2 --timeout 600 \
  --out "$out/report" > "$out/log" 2>&1 &
pid=$!
i=0
until grep -q '"id": "sparsegrid.hard.level1"' "$out/report/results.json" 2>/dev/null; do
  i=$((i + 1))
  if [ $i -gt 1200 ]; then echo "the first case never appeared in the running snapshot"; kill -KILL $pid; cat "$out/log"; exit 1; fi
  sleep 0.1
done
grep -q '"running": true' "$out/report/results.json" || { echo "the snapshot is not marked running"; exit 1; }
kill -INT $pid
wait $pid
status=$?
cat "$out/log"
[ $status -eq 130 ] || { echo "exit status $status, expected 130"; exit 1; }
grep -q "INTERRUPTED by SIGINT: partial report" "$out/log" || { echo "the summary does not say the run was interrupted"; exit 1; }
grep -qi "partial" "$out/report/index.html" || { echo "index.html does not say the report is partial"; exit 1; }
# The cases' processes are forks of voxref: their command line is the run's own.
sleep 0.5
if pgrep -f -- "--out $out/report" > /dev/null; then
  echo "a case's process outlived the run:"; pgrep -af -- "--out $out/report"; exit 1
fi
"$check" "$out/report/results.json" --expect-interrupted --expect-status sparsegrid.hard.level1=pass --min-cases 1
