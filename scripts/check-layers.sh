#!/usr/bin/env bash
# The module layering (docs/architecture.md): no module includes a module above it.
# Reads the layers from cmake/layers.txt (the one place that says them), checks that every
# module uses only modules listed before it, then every #include "module/..." of every
# module's sources against the modules it may use; prints each violation (file: include) and
# exits 1 if there is one. A permission the module neither includes nor links (its
# CMakeLists.txt naming another module's target) is a warning: the line should shrink. Run by CTest.
set -euo pipefail
cd "$(dirname "$0")/.."

declare -A ALLOWED=()
declare -A USED=()  # the modules each module's sources include or its CMakeLists.txt links
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
      USED[$module]+=" $used "
      case " ${ALLOWED[$module]} " in
        *" $used "*) ;;
        *) echo "$file: includes \"$include\" ($module may not use $used)"; violations=$((violations + 1)) ;;
      esac
    done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file")
  done < <(find "$module" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) | sort)
done

# The library targets each module's CMakeLists.txt (and the cmake/*.cmake files it includes) adds.
declare -A OWNER=()
for module in "${ORDER[@]}"; do
  lists=$(sed -n 's|^[[:space:]]*include(${PROJECT_SOURCE_DIR}/\(cmake/[^)]*\.cmake\)).*|\1|p' "$module/CMakeLists.txt" 2>/dev/null || true)
  for target in $(cat "$module/CMakeLists.txt" $lists 2>/dev/null | sed -n 's/.*add_library(\(lfd_[a-z0-9_]*\).*/\1/p'); do
    OWNER[$target]=$module
  done
done
for module in "${ORDER[@]}"; do
  for target in $(grep -o 'lfd_[a-z0-9_]*' "$module/CMakeLists.txt" 2>/dev/null | sort -u); do
    owner=${OWNER[$target]:-}
    [ -n "$owner" ] && [ "$owner" != "$module" ] && USED[$module]+=" $owner "
  done
  for permitted in ${ALLOWED[$module]}; do
    case "${USED[$module]:-}" in
      *" $permitted "*) ;;
      *) echo "cmake/layers.txt: $module may use $permitted but never includes it" ;;
    esac
  done
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
