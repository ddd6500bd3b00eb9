#!/usr/bin/env bash
# The module layering (docs/architecture.md): no module includes a module above it.
# Reads the layers from cmake/layers.txt (the one place that says them), checks that every
# module uses only modules listed before it, then every #include "module/..." of every
# module's sources against the modules it may use; prints each violation (file: include) and
# exits 1 if there is one. Run by CTest.
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A ALLOWED=()
ORDER=()
violations=0
while read -r module build uses; do
  case "$module" in ''|'#'*) continue ;; esac
  for used in $uses; do
    if [ -z "${ALLOWED[$used]+x}" ]; then
      echo "cmake/layers.txt: $module uses $used, which is not listed before it"
      violations=$((violations + 1))
    fi
  done
  ALLOWED[$module]="$uses"
  ORDER+=("$module")
done < cmake/layers.txt

# The module an include path belongs to: the longest listed folder it lies in
# (calib/solver/lens_solver.hpp -> calib/solver, calib/calibrate.hpp -> calib).
module_of() {
  local best="" m
  for m in "${ORDER[@]}"; do
    case "$1" in "$m"/*) [ ${#m} -gt ${#best} ] && best=$m ;; esac
  done
  echo "$best"
}

for module in "${ORDER[@]}"; do
  [ -d "$module" ] || { echo "cmake/layers.txt: $module is not a folder"; violations=$((violations + 1)); continue; }
  while IFS= read -r file; do
    while IFS= read -r include; do
      used=$(module_of "$include")
      [ -n "$used" ] || continue  # a system header spelled with quotes, or tests/
      [ "$used" = "$module" ] && continue
      case " ${ALLOWED[$module]} " in
        *" $used "*) ;;
        *) echo "$file: includes \"$include\" ($module may not use $used)"; violations=$((violations + 1)) ;;
      esac
    done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file")
  done < <(find "$module" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) | sort)
done

# Every folder with sources is a listed module (a new folder gets a line in cmake/layers.txt).
while IFS= read -r dir; do
  dir=${dir#./}
  case "$dir" in tests|tests/*|fuzz|build*|.*|data*|docs*|scripts*|cmake*|out*|bundle*) continue ;; esac
  if [ -z "${ALLOWED[$dir]+x}" ]; then
    echo "$dir: has sources but no line in cmake/layers.txt"
    violations=$((violations + 1))
  fi
done < <(find . -name '*.cpp' -not -path './build*' -not -path './tests/*' -not -path './fuzz/*' -printf '%h\n' | sort -u)

if [ "$violations" -gt 0 ]; then
  echo "check-layers: $violations violation(s)"
  exit 1
fi
echo "check-layers: ${#ORDER[@]} modules, each includes only the modules below it"
