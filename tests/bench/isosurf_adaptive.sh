#!/usr/bin/env bash
# isosurf adaptive against exact marching cubes on the Cranium CT bone surface, by distance
# band around the focus (docs/isosurf.md 5 "Measured"). One JSON line per (edge rule, band):
# triangles of exact and adaptive whose three vertices lie in the band, their ratio, and the
# geometric deviation measured by fcompare (an independent program): from the adaptive
# triangles of the band to the whole exact surface (a_to_b) and from the exact triangles of
# the band to the whole adaptive surface (b_to_a, what the adaptive surface misses there).
# Comparing a band with the whole other surface keeps the band's cut edges out of the figure.
#
#   tests/bench/isosurf_adaptive.sh [BUILD_DIR] [FOCUS] [R0]
#   (defaults: build, 122,122,80 = the volume centre, 16 mm; the Cranium CT comes from
#    scripts/fetch-test-data.sh)
set -euo pipefail
build="${1:-build}"
focus="${2:-122,122,80}"
r0="${3:-16}"
here="$(cd "$(dirname "$0")" && pwd)"
FX="python3 $here/../cli/isovol/fixtures.py"
ct="${FEST_TESTDATA:-$HOME/.cache/fest/testdata}/volumes/cranium.nrrd"
[ -f "$ct" ] || { echo "isosurf_adaptive.sh: $ct missing (scripts/fetch-test-data.sh)" >&2; exit 77; }
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT

iso=(--iso 225.5 --cap -1024 --threads 1)
"$build/bin/isosurf" exact "$ct" "${iso[@]}" -o "$W/exact.ply" --report "$W/exact.json"
# distance bands of the rule L_f(d) = floor(log2(1 + d/r0)): levels 0, 1, 2, 3, >= 4
bands=$(awk -v r="$r0" 'BEGIN { printf "0:%g %g:%g %g:%g %g:%g %g:1e9", r, r, 3*r, 3*r, 7*r, 7*r, 15*r, 15*r }')
dev() {  # dev A B -> max distance from the samples of A to the surface B
  "$build/bin/fcompare" "$1" "$2" --ignore-counts --ignore-topology --report "$W/fc.json" >/dev/null 2>&1 || true
  jq .metrics.max_a_to_b "$W/fc.json"
}
for rule in transitions all; do
  "$build/bin/isosurf" adaptive "$ct" "${iso[@]}" --focus "$focus" --focus-radius "$r0" --max-error inf \
    --edge-rule "$rule" -o "$W/ad.ply" --report "$W/ad.json"
  whole_ab=$(dev "$W/ad.ply" "$W/exact.ply")
  whole_ba=$(dev "$W/exact.ply" "$W/ad.ply")
  jq -c --arg rule "$rule" --arg focus "$focus" --argjson r0 "$r0" --slurpfile ex "$W/exact.json" \
    --argjson ab "$whole_ab" --argjson ba "$whole_ba" \
    '{case: "cranium bone 225.5, whole surface", method: "isosurf adaptive", edge_rule: $rule, focus: $focus, r0_mm: $r0,
      triangles: .triangles, exact_triangles: $ex[0].triangles, reduction: ($ex[0].triangles / .triangles),
      closed: .closed, leaves_per_level: .leaves_per_level[0:5], extract_s: .time_s.extract,
      dev_a_to_b_mm: $ab, dev_b_to_a_mm: $ba}' "$W/ad.json"
  for b in $bands; do
    lo=${b%:*} hi=${b#*:}
    read -r _ fe < <($FX crop "$W/exact.ply" "$W/e_band.ply" "$focus" "$lo" "$hi")
    read -r _ fa < <($FX crop "$W/ad.ply" "$W/a_band.ply" "$focus" "$lo" "$hi")
    ab=null ba=null
    [ "$fa" -gt 0 ] && ab=$(dev "$W/a_band.ply" "$W/exact.ply")
    [ "$fe" -gt 0 ] && ba=$(dev "$W/e_band.ply" "$W/ad.ply")
    jq -nc --arg rule "$rule" --arg band "$lo-$hi mm" --argjson fe "$fe" --argjson fa "$fa" --argjson ab "$ab" --argjson ba "$ba" \
      '{case: "cranium bone 225.5, band around the focus", method: "isosurf adaptive", edge_rule: $rule, band: $band,
        exact_triangles: $fe, triangles: $fa, reduction: (if $fa > 0 then $fe / $fa else null end),
        dev_a_to_b_mm: $ab, dev_b_to_a_mm: $ba}'
  done
done
