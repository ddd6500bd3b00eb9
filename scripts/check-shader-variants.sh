#!/usr/bin/env bash
# The reference GLSL front end over every shader variant the GL tests built (docs/gpu.md
# "Drivers and limits"): each file LFD_SHADER_DUMP wrote (gpu/gl/shader_dump.hpp: the version,
# the variant's defines, the embedded source) is compiled by glslangValidator as GLSL 4.50 (the
# OpenGL ES variants as GLSL ES 3.10, from their #version), so a
# construct Mesa tolerates but the standard does not fails here. An error is printed as
# FILE:LINE: message with the repository file and line (the `//! files:` list and #line numbers
# the embedder wrote), then the variant. Exits 1 on any error, or when DIR holds fewer than
# MIN variants (the GL tests did not run first: CTest orders it after them with a fixture).
#   check-shader-variants.sh DIR [MIN]
#   check-shader-variants.sh --self-test   a non-standard construct put in on purpose must fail
set -euo pipefail
command -v glslangValidator >/dev/null || { echo "glslangValidator not found (Debian: glslang-tools)"; exit 1; }

# Compiles one variant; prints its errors with repository files and lines; returns glslang's status.
check_variant() {
  local variant=$1 out status=0
  out=$(glslangValidator "$variant" 2>&1) || status=$?
  [ "$status" -eq 0 ] && return 0
  # Source-string number S of "ERROR: S:L:" is the S-th file of the first `//! files:` line.
  awk -v variant="$variant" '
    NR == FNR { if (FNR <= 40 && $0 ~ /^\/\/! files:/) { n = split(substr($0, 12), files, " ") } next }
    /^(ERROR|WARNING): [0-9]+:[0-9]+:/ {
      split($2, where, ":"); s = where[1] + 1; line = where[2]
      message = $0; sub(/^[A-Z]+: [0-9]+:[0-9]+: */, "", message)
      file = (s >= 1 && s <= n) ? files[s] : variant
      if ($1 == "ERROR:" && message !~ /compilation terminated/) printf "%s:%s: %s (variant %s)\n", file, line, message, variant
      next
    }
    /^ERROR:/ { print variant ": " $0 }
  ' "$variant" <(printf '%s\n' "$out")
  return "$status"
}

if [ "${1:-}" = "--self-test" ]; then
  dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
  # A standard variant passes ...
  printf '%s\n' '#version 450 core' '//! files: gpu/example/shaders/probe.comp.glsl' '#line 1 0' \
    'layout(local_size_x = 64) in;' 'layout(std430, binding = 0) buffer Out { float v[]; };' \
    'void main() {' '  v[gl_GlobalInvocationID.x] = 1.0;' '}' > "$dir/good.comp"
  check_variant "$dir/good.comp" || { echo "self-test: a standard shader was rejected"; exit 1; }
  # ... and one with an implicit float-to-int conversion (not in GLSL 4.50) is refused, naming
  # the repository file and its line 4.
  sed 's/  v\[gl_GlobalInvocationID.x\] = 1.0;/  int i = 1.5; v[i] = 1.0;/' "$dir/good.comp" > "$dir/bad.comp"
  if out=$(check_variant "$dir/bad.comp"); then echo "self-test: a non-standard shader passed"; exit 1; fi
  case "$out" in
    *"gpu/example/shaders/probe.comp.glsl:4:"*) echo "self-test: refused as expected: $out" ;;
    *) echo "self-test: the error does not name the file and line: $out"; exit 1 ;;
  esac
  exit 0
fi

dir=${1:?usage: check-shader-variants.sh DIR [MIN] | --self-test}
min=${2:-1}
shopt -s nullglob
variants=("$dir"/*.comp "$dir"/*.vert "$dir"/*.frag)
if [ "${#variants[@]}" -lt "$min" ]; then
  echo "check-shader-variants: $dir holds ${#variants[@]} variants, fewer than $min (run the GL tests first)"
  exit 1
fi
failed=0
for v in "${variants[@]}"; do check_variant "$v" || failed=$((failed + 1)); done
if [ "$failed" -gt 0 ]; then
  echo "check-shader-variants: $failed of ${#variants[@]} variants are not standard GLSL (4.50; ES 3.10 for the OpenGL ES variants)"
  exit 1
fi
echo "check-shader-variants: ${#variants[@]} variants, each standard GLSL 4.50 or ES 3.10 (glslangValidator)"
