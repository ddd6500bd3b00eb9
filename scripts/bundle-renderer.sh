#!/usr/bin/env bash
# Builds the renderer-only lfd (-DLFD_RENDER_ONLY=ON, Release) and packs it into a folder that
# runs on a machine with only a GPU driver: the program, its data, and every shared library it
# links except glibc's own and the OpenGL/EGL libraries, which must come from the machine (the
# driver's, through libglvnd). run.sh sets LD_LIBRARY_PATH to the bundled libraries and runs lfd.
#
#   scripts/bundle-renderer.sh [OUT]          OUT default: bundle/lfd-renderer (git-ignored)
#   bundle/lfd-renderer/run.sh version
#   bundle/lfd-renderer/run.sh bench render --backend gl --json render-gl.json
#
# Environment: LFD_BUNDLE_BUILD_DIR (default build-bundle), CMAKE_CXX_COMPILER_LAUNCHER (e.g.
# ccache), JOBS (ninja -j), LFD_BUNDLE_TESTS=1 to add the GL test programs (tests/: the GL
# renderers, shaders and interlacer against their CPU twins) that scripts/gpu-table.sh runs
# first. docs/performance.md says how to run the benchmark with it on a GPU machine.
#
# The bundle leaves playback out (-DLFD_WITH_PLAYBACK=OFF: no lfd play or lfd serve): FFmpeg's
# codec libraries would make it 176 MB, past what travels to a GPU machine (64 MiB).
set -euo pipefail
cd "$(dirname "$0")/.."

out=${1:-bundle/lfd-renderer}
build=${LFD_BUNDLE_BUILD_DIR:-build-bundle}
launcher=()
if [ -n "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER="$CMAKE_CXX_COMPILER_LAUNCHER")
fi

with_tests=${LFD_BUNDLE_TESTS:-0}
test_programs=(lfd_gpu_tests lfd_lightfield_tests)
targets=(lfd)
if [ "$with_tests" = 1 ]; then targets+=("${test_programs[@]}"); fi
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLFD_RENDER_ONLY=ON -DLFD_WITH_PLAYBACK=OFF \
  -DLFD_BUILD_TESTS=$([ "$with_tests" = 1 ] && echo ON || echo OFF) "${launcher[@]}" >/dev/null
ninja -C "$build" ${JOBS:+-j "$JOBS"} "${targets[@]}"

# The program, its data and the notices, laid out as installed (bin/, share/lfd/): lfd finds its
# data relative to itself (util/data_dir.hpp).
rm -rf "$out"
cmake --install "$build" --prefix "$out" --component runtime >/dev/null
# Only the program, its data and the notices: no udev rules.
rm -rf "$out/lib/udev"

# Shared libraries: everything ldd resolves, except
#   glibc's own (the loader, libc, libm, libpthread, libdl, librt, libresolv, ...): they must
#     match the machine's loader, and every Linux has them;
#   OpenGL and EGL (libEGL, libGL, libGLX, libGLdispatch, libOpenGL, libGLES): the driver's,
#     through libglvnd; lfd's libepoxy loads them at run time.
excluded='^(ld-linux.*|linux-vdso.*|libc|libm|libmvec|libpthread|libdl|librt|libresolv|libutil|libanl|libnsl|libBrokenLocale|libcrypt|libEGL.*|libGL.*|libGLX.*|libGLdispatch|libOpenGL|libGLES.*|libglvnd.*)\.so'
# The GL test programs read their fixtures from this checkout's path (tests/test_data.hpp), which
# scripts/gpu-table.sh links to the repository on the GPU machine.
programs=("$out/bin/lfd")
if [ "$with_tests" = 1 ]; then
  mkdir -p "$out/tests"
  for t in "${test_programs[@]}"; do
    cp "$build/tests/$t" "$out/tests/$t"
    programs+=("$out/tests/$t")
  done
  pwd > "$out/tests/source_dir.txt"
fi
mkdir -p "$out/lib"
bundled=()
while read -r name arrow path _; do
  [ "$arrow" = "=>" ] && [ -f "$path" ] || continue
  if [[ "$name" =~ $excluded ]]; then continue; fi
  [ -f "$out/lib/$name" ] && continue
  cp -L "$path" "$out/lib/$name"
  bundled+=("$name")
done < <(for p in "${programs[@]}"; do ldd "$p"; done)

cat > "$out/run.sh" <<'EOF'
#!/usr/bin/env bash
# Runs the bundled lfd with its own libraries (lib/) before the machine's; OpenGL/EGL and glibc
# come from the machine. Arguments go to lfd.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
exec "$here/bin/lfd" "$@"
EOF
chmod +x "$out/run.sh"

echo "bundle-renderer: $out ($(du -sh "$out" | cut -f1)): bin/lfd, share/lfd, run.sh and ${#bundled[@]} libraries:"
echo "  ${bundled[*]}"
echo "bundle-renderer: the machine must provide glibc >= $(ldd --version | head -1 | awk '{print $NF}') and OpenGL/EGL (libEGL.so.1 from libglvnd + the GPU driver)"
