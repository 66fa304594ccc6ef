#!/usr/bin/env bash
# Start-up of every fest tool (issue 21): the median of 10 warm runs of `TOOL --version`
# (hyperfine -N --warmup 2 -r 10) and the number of shared libraries the dynamic linker
# maps (ldd, the vdso not counted), with netpbm's pamscale, vips, gdalinfo and ImageMagick's
# convert measured the same way in the same run as anchors.
#
#   tests/bench/startup.sh [BUILD_BIN]          (default: build/bin)
#
# The tools are the folders of tools/. One JSON line per program on standard output:
#   {"bench":"startup","tool":"fconv","kind":"fest","median_ms":4.1,"mean_ms":..,"min_ms":..,"cpu_ms":..,
#    "mapped_libs":31,"pass":true}
# cpu_ms is the mean user + system time: on a loaded machine it moves less than wall time.
# Limits (issue 21; README.md, start-up conventions): --version <= 15 ms warm and <= 40
# mapped libraries. A fest tool above either gets "pass":false and a FAIL line on standard
# error, and the script exits 1; a tool not built gets a "skipped" line (and fails too).
# Anchors are never judged. Needs hyperfine and jq (Debian: hyperfine, jq).
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
case "${1:-}" in -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;; esac
BIN=${1:-$root/build/bin}
MAX_MS=${MAX_MS:-15} MAX_LIBS=${MAX_LIBS:-40}
for c in hyperfine jq ldd; do
  command -v "$c" >/dev/null 2>&1 || { echo "startup.sh: $c is needed (Debian: $c)" >&2; exit 2; }
done
[ -d "$BIN" ] || { echo "startup.sh: no folder $BIN (build the tools first)" >&2; exit 2; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/fest-startup.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

# libs PROGRAM: shared objects ldd lists (resolved or not), the vdso left out.
libs() { ldd "$1" 2>/dev/null | grep -v -c 'linux-vdso\|statically linked'; }

# measure NAME KIND PROGRAM ARGS...: prints the JSON line; returns 1 when a fest tool fails.
measure() {
  local name=$1 kind=$2 prog=$3; shift 3
  local cmd n stats
  cmd=$(printf '%q ' "$prog" "$@")
  if ! hyperfine -N --warmup 2 -r 10 --style none --export-json "$WORK/h.json" "$cmd" >/dev/null 2>"$WORK/err"; then
    printf '{"bench":"startup","tool":"%s","kind":"%s","failed":"%s"}\n' "$name" "$kind" \
      "$(grep -v '^ *$' "$WORK/err" | head -c 200 | tr '\n"\\' '   ')"
    [ "$kind" = anchor ] && return 0
    echo "startup.sh: FAIL $name: '$cmd' did not run" >&2; return 1
  fi
  n=$(libs "$prog")
  stats=$(jq -c '.results[0] | {median_ms: (.median * 1e5 | round / 100), mean_ms: (.mean * 1e5 | round / 100),
                               min_ms: (.min * 1e5 | round / 100),
                               cpu_ms: ((.user + .system) * 1e5 | round / 100)}' "$WORK/h.json")
  local pass=true why=""
  if [ "$kind" = fest ]; then
    if jq -e --argjson max "$MAX_MS" '.median_ms > $max' <<<"$stats" >/dev/null; then
      why="median $(jq .median_ms <<<"$stats") ms > $MAX_MS ms"
    fi
    [ "$n" -gt "$MAX_LIBS" ] && why="${why:+$why, }$n mapped libraries > $MAX_LIBS"
    [ -n "$why" ] && pass=false
  fi
  jq -c --arg t "$name" --arg k "$kind" --argjson libs "$n" --argjson pass "$pass" \
    '{bench: "startup", tool: $t, kind: $k} + . + {mapped_libs: $libs} + (if $k == "fest" then {pass: $pass} else {} end)' <<<"$stats"
  if [ "$pass" = false ]; then
    echo "startup.sh: FAIL $name: $why" >&2
    return 1
  fi
}

failed=0
for dir in "$root"/tools/*/; do
  t=$(basename "$dir")
  if [ ! -x "$BIN/$t" ]; then
    printf '{"bench":"startup","tool":"%s","kind":"fest","skipped":"not built"}\n' "$t"
    echo "startup.sh: FAIL $t: $BIN/$t is not built" >&2; failed=1; continue
  fi
  measure "$t" fest "$BIN/$t" --version || failed=1
done

# Anchors. ImageMagick: its own binary (a `convert` first in PATH may be a wrapper script).
anchor() {  # name program args...
  if command -v "$2" >/dev/null 2>&1; then measure "$1" anchor "$(command -v "$2")" "${@:3}"
  else printf '{"bench":"startup","tool":"%s","kind":"anchor","skipped":"%s not installed"}\n' "$1" "$2"; fi
}
anchor pamscale pamscale --version
anchor vips vips --version
anchor gdalinfo gdalinfo --version
IM=convert
for c in magick convert-im6.q16 convert; do
  if command -v "$c" >/dev/null 2>&1 && "$c" -version 2>/dev/null | grep -q ImageMagick; then IM=$c; break; fi
done
anchor convert "$IM" --version
exit "$failed"
