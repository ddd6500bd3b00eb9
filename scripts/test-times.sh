#!/usr/bin/env bash
# Where the test suite's time goes (docs/performance.md "The test suite's time"): reads CTest's
# output (a file, or standard input) and prints each suite's summed test time, the most first,
# with its test count; CTest runs each test in its own process, so a suite's shared fixture is
# paid once per test. Example:
#   ctest --test-dir build -j2 | tee ctest.log; bash scripts/test-times.sh ctest.log
set -euo pipefail
top=${TOP:-20}
sed -nE 's/.*Test +#[0-9]+: ([^ ]+) .* ([0-9.]+) sec$/\1 \2/p' "${1:-/dev/stdin}" |
  awk -v top="$top" '{
      suite = $1; sub(/\..*/, "", suite); sub(/^.*\//, "", suite)
      t[suite] += $2; n[suite]++; total += $2
    }
    END {
      printf "%9s %5s  %s\n", "seconds", "tests", "suite"
      for (s in t) printf "%9.1f %5d  %s\n", t[s], n[s], s | "sort -rn | head -" top
      close("sort -rn | head -" top)
      printf "%9.1f %5d  all tests (summed; the wall time is less with -j)\n", total, NR
    }'
