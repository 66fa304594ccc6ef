#!/usr/bin/env bash
# contact_sheet.sh OUT.png A.png B.png ...: the grey images side by side, left to right,
# separated by 4-pixel white gutters (all of the same height). Made with fconv and awk
# only, so the demo needs nothing beyond fest.
set -eu
out=$1; shift
FCONV=${FCONV:-fconv}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
i=0
for f in "$@"; do "$FCONV" --to pgm --ascii "$f" -o "$tmp/$i.pgm"; i=$((i + 1)); done
awk -v n="$i" -v gutter=4 '
  FNR == 1 { file++; tok = 0 }
  { for (k = 1; k <= NF; k++) {
      tok++
      if (tok == 2) w[file] = $k; else if (tok == 3) h = $k; else if (tok == 4) maxv = $k
      else if (tok > 4) px[file, tok - 5] = $k } }
  END {
    total = 0; for (f = 1; f <= n; f++) total += w[f]; total += gutter * (n - 1)
    print "P2"; print total, h; print maxv
    for (y = 0; y < h; y++) {
      line = ""
      for (f = 1; f <= n; f++) {
        for (x = 0; x < w[f]; x++) line = line px[f, y * w[f] + x] " "
        if (f < n) for (g = 0; g < gutter; g++) line = line maxv " "
      }
      print line
    } }' $(for ((k = 0; k < i; k++)); do echo "$tmp/$k.pgm"; done) >"$tmp/sheet.pgm"
"$FCONV" "$tmp/sheet.pgm" -o "$out"
