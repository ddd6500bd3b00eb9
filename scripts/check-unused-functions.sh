#!/usr/bin/env bash
# Functions declared but never used (the CTest test UnusedFunctions): for every function or
# method a module's header declares (*.hpp in the module folders of cmake/layers.txt), counts
# the whole-word occurrences of its name, outside comments and strings, in the C++ sources of
# the modules (apps/ and bench/ among them), tests/ and fuzz/, leaving out the lines that
# declare or define a function of that name. A name found nowhere else is printed as
# `file:line: NAME is declared but never used` and the script exits 1. No build needed: the
# declarations are found by their shape on one line (`type name(` or, at column 0, `name(`
# after a return type on the line before); operators and constructors are skipped, overloads
# share their name. What a library calls by name (a virtual hook, a callback) goes in
# scripts/unused-functions-allowed.txt with its reason. Run by CTest.
set -euo pipefail
cd "$(dirname "$0")/.."

modules=()
while read -r module _; do
  case "$module" in ''|'#'*) continue ;; esac
  modules+=("$module")
done < cmake/layers.txt

# Each module's own files (its subfolders that are modules have their own line), then the rest.
headers=()
sources=()
for module in "${modules[@]}"; do
  while IFS= read -r f; do
    sources+=("$f")
    case "$f" in *.hpp) headers+=("$f") ;; esac
  done < <(find "$module" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) | sort)
done
for dir in tests fuzz; do
  while IFS= read -r f; do sources+=("$f"); done < <(find "$dir" \( -name '*.cpp' -o -name '*.hpp' \) | sort)
done

read -r -d '' program <<'AWK' || true
  # The name a line declares or defines, or "": `[qualifiers] type [Class::]name(`, or
  # `[Class::]name(` at column 0 (the return type on the line before).
  function declared(line,    m, first, name) {
    if (match(line, /^[ \t]*([A-Za-z_][A-Za-z0-9_:<>,*&]*[ \t]+|\[\[[a-z_]+\]\][ \t]+)+[*&]*([A-Za-z_][A-Za-z0-9_]*::)*~?[A-Za-z_][A-Za-z0-9_]*[ \t]*\(/)) {
      m = substr(line, RSTART, RLENGTH)
      first = m
      sub(/^[ \t]*/, "", first)
      sub(/[^A-Za-z0-9_].*/, "", first)
      if (first in statement) return ""
    } else if (match(line, /^([A-Za-z_][A-Za-z0-9_]*::)*~?[A-Za-z_][A-Za-z0-9_]*\(/)) {
      m = substr(line, RSTART, RLENGTH)
    } else {
      return ""
    }
    sub(/[ \t]*\($/, "", m)
    name = m
    sub(/.*[^A-Za-z0-9_]/, "", name)
    if (name in statement) return ""
    return name
  }
  BEGIN {
    split("return if else while for switch case throw delete new using typedef goto do co_return co_yield co_await sizeof alignof decltype static_assert catch operator not and or", kw, " ")
    for (i in kw) statement[kw[i]] = 1
    while ((getline l < allowed) > 0) {
      sub(/#.*/, "", l)
      gsub(/[ \t]/, "", l)
      if (l != "") allow[l] = 1
    }
    reading_headers = 1
  }
  reading_headers && $0 == "--" { reading_headers = 0; next }
  reading_headers { is_header[$0] = 1; next }
  FNR == 1 { in_block = 0 }
  {
    line = $0
    # Neither strings nor comments count: a name mentioned only in one is still unused (and
    # a "//" or "/*" in a string opens no comment).
    gsub(/\\\\/, "", line)
    gsub(/'(\\.|[^'\\])'/, "0", line)
    gsub(/"(\\.|[^"\\])*"/, "\"\"", line)
    if (in_block) {
      if (index(line, "*/") == 0) next
      line = substr(line, index(line, "*/") + 2)
      in_block = 0
    }
    sub(/\/\/.*/, "", line)
    while ((s = index(line, "/*")) > 0) {
      rest = substr(line, s + 2)
      e = index(rest, "*/")
      if (e == 0) { line = substr(line, 1, s - 1); in_block = 1; break }
      line = substr(line, 1, s - 1) " " substr(rest, e + 2)
    }
    d = declared(line)
    if (d != "" && FILENAME in is_header && !(d in first_declared))
      first_declared[d] = FILENAME ":" FNR
    # Every other word on the line is a use.
    n = split(line, words, /[^A-Za-z0-9_]+/)
    for (i = 1; i <= n; ++i)
      if (words[i] != "" && words[i] != d) uses[words[i]]++
  }
  END {
    bad = 0
    for (d in first_declared) {
      if (d in uses || d in allow) continue
      print first_declared[d] ": " d " is declared but never used" | "sort"
      ++bad
    }
    close("sort")
    for (a in allow)
      if (!(a in first_declared)) print "scripts/unused-functions-allowed.txt: " a " is declared nowhere (remove its line)"
    if (bad) { print "check-unused-functions: " bad " unused function(s)"; exit 1 }
    declared_count = 0
    for (d in first_declared) ++declared_count
    print "check-unused-functions: " declared_count " function names declared in the modules' headers, each used"
  }
AWK

{
  printf '%s\n' "${headers[@]}"
  echo "--"
} | awk -v allowed=scripts/unused-functions-allowed.txt "$program" - "${sources[@]}"
