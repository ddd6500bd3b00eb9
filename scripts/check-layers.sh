#!/usr/bin/env bash
# The module layering (docs/architecture.md): no module includes a module above it.
# Checks every #include "module/..." of every module's sources against the modules it may use;
# prints each violation (file: include) and exits 1 if there is one. Run by CTest.
set -euo pipefail
cd "$(dirname "$0")/.."

# module -> the modules its sources may include (besides itself)
declare -A ALLOWED=(
  [util]=""
  [calib/display]="util"
  [calib/device]="util calib/display"
  [render]="util"
  [voxel]="util render"
  [interlace]="util calib/display render"
  [gpu]="util calib/display render voxel interlace"
  [viewer]="util calib/display render voxel interlace gpu"
  [calib]="util calib/display"
  [calib/live]="util calib/display render voxel interlace gpu calib"
  [validate]="util calib/display render interlace calib"
  [report]="util calib/display render interlace calib validate"
  [pipeline]="util calib/display render voxel interlace gpu calib validate report"
  [bench]="util calib/display render voxel interlace gpu"
  [apps]="util calib/display calib/device render voxel interlace gpu viewer bench calib calib/live validate report pipeline"
)

# The module an include path belongs to: calib/display/x.hpp -> calib/display, calib/x.hpp -> calib.
module_of() {
  case "$1" in
    calib/display/*) echo calib/display ;;
    calib/live/*) echo calib/live ;;
    calib/device/*) echo calib/device ;;
    *) echo "${1%%/*}" ;;
  esac
}

violations=0
for module in "${!ALLOWED[@]}"; do
  [ -d "$module" ] || continue
  while IFS= read -r file; do
    while IFS= read -r include; do
      used=$(module_of "$include")
      [ -d "$used" ] || continue  # a system header spelled with quotes
      [ "$used" = "$module" ] && continue
      case " ${ALLOWED[$module]} " in
        *" $used "*) ;;
        *) echo "$file: includes \"$include\" ($module may not use $used)"; violations=$((violations + 1)) ;;
      esac
    done < <(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$file")
  done < <(find "$module" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) | sort)
done

if [ "$violations" -gt 0 ]; then
  echo "check-layers: $violations include(s) reach a module above their own"
  exit 1
fi
echo "check-layers: every module includes only the modules below it"
