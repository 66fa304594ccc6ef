#!/usr/bin/env bash
# Benchmark of `resample` against its anchors in the same run (docs/resample.md "Figures reproduced", Z1;
# R1/R2 of docs/resample.md "Separable passes and their order"): libvips (`vips`), ImageMagick (`convert`) and OpenImageIO (`oiiotool`), each
# skipped with a JSON note when not installed (Debian: libvips-tools, imagemagick,
# openimageio-tools). One JSON line per case on standard output.
#
#   tests/bench/resample_bench.sh [BUILD_BIN]      (default: build/bin)
#
# Z1: the 2048² zone plate (ν_max = 1 cycle per output pixel after the 8x reduction) as a
#     16-bit PGM that every tool filters as plain values, reduced to 256² with lanczos3,
#     mitchell and point sampling; AE/PR measured by `resample metrics` for each tool.
# R1: 4928×3279 RGB8 PPM -> 852×567, lanczos3, end to end (min of 3 runs), resample in
#     gamma-encoded (codes) and linear-light mode; peak RSS and CPU seconds (user + system,
#     the figure to compare on a shared machine).
# R2: 8192² one-channel float PFM -> 1024², mitchell.
set -u
BIN=${1:-build/bin}
R="$BIN/resample"
[ -x "$R" ] || { echo "resample_bench: no $R (build the resample target first)" >&2; exit 2; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/resample-bench.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
RUNS=${RUNS:-3}

# ImageMagick: `magick` (7) or the Debian 6 binary; a stand-in `convert` that is not
# ImageMagick is skipped.
IM=""
for c in magick convert-im6.q16 convert; do
  if command -v "$c" >/dev/null 2>&1 && "$c" -version 2>/dev/null | grep -q ImageMagick; then IM=$(command -v "$c"); break; fi
done
have() { command -v "$1" >/dev/null 2>&1; }

# timed CMD...: runs RUNS times, sets $secs (minimum wall time), $peak_mb (peak RSS of
# the fastest run) and $cpu (minimum user + system CPU seconds, all threads: the figure
# to compare on a shared machine); $ok = 0 when the command failed.
timed() {
  secs="" peak_mb="" cpu="" ok=1
  local i t m u s c
  for ((i = 0; i < RUNS; i++)); do
    if ! /usr/bin/time -f "%e %M %U %S" -o "$WORK/time" "$@" >/dev/null 2>"$WORK/err"; then ok=0; return; fi
    read -r t m u s <"$WORK/time"
    c=$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.2f", u + s }')
    if [ -z "$secs" ] || awk -v a="$t" -v b="$secs" 'BEGIN { exit !(a < b) }'; then secs=$t; peak_mb=$((m / 1024)); fi
    if [ -z "$cpu" ] || awk -v a="$c" -v b="$cpu" 'BEGIN { exit !(a < b) }'; then cpu=$c; fi
  done
}

json_skip() { printf '{"bench":"resample","case":"%s","tool":"%s","skipped":"%s"}\n' "$1" "$2" "$3"; }

# --- Z1 ------------------------------------------------------------------------------------
"$R" render --scene zoneplate --param numax=0.125 --size 2048x2048 --spp 4 --pattern regular --depth 16 --colorspace linear \
  --to pgm -o "$WORK/zp.pgm"
zmetrics() { "$R" metrics --zoneplate numax=1,width=256,height=256 --domain encoded "$1"; }
z1() {  # tool kernel command...
  local tool=$1 kernel=$2; shift 2
  RUNS=1 timed "$@"
  if [ "$ok" -ne 1 ]; then json_skip Z1 "$tool" "failed: $(head -c 200 "$WORK/err" | tr '\n"' ' ')"; return; fi
  local m
  m=$(zmetrics "$WORK/z.pgm") || { json_skip Z1 "$tool" "unreadable output"; return; }
  printf '{"bench":"resample","case":"Z1","tool":"%s","kernel":"%s","seconds":%s,"ae":%s,"pr":%s}\n' "$tool" "$kernel" \
    "$secs" "$(jq .ae <<<"$m")" "$(jq .pr <<<"$m")"
}
for k in lanczos3 mitchell point; do
  z1 resample "$k" "$R" resize "$WORK/zp.pgm" --size 256x256 --filter "$k" --colorspace linear -o "$WORK/z.pgm"
  if have vips; then
    vk=$k; [ "$k" = point ] && vk=nearest
    z1 vips "$k" vips resize "$WORK/zp.pgm" "$WORK/z.pgm" 0.125 --kernel "$vk" --gap 0
  else json_skip Z1 vips "vips not installed (libvips-tools)"; fi
  if have oiiotool; then
    if [ "$k" = point ]; then
      z1 oiiotool "$k" oiiotool "$WORK/zp.pgm" --resample:interp=0 256x256 -o "$WORK/z.pgm"
    else
      z1 oiiotool "$k" oiiotool "$WORK/zp.pgm" --resize:filter="$k" 256x256 -o "$WORK/z.pgm"
    fi
  else json_skip Z1 oiiotool "oiiotool not installed (openimageio-tools)"; fi
  if [ -n "$IM" ]; then
    case $k in
      lanczos3) z1 imagemagick "$k" "$IM" "$WORK/zp.pgm" -filter Lanczos -resize 256x256 -depth 16 "$WORK/z.pgm" ;;
      mitchell) z1 imagemagick "$k" "$IM" "$WORK/zp.pgm" -filter Mitchell -resize 256x256 -depth 16 "$WORK/z.pgm" ;;
      point) z1 imagemagick "$k" "$IM" "$WORK/zp.pgm" -sample 256x256 -depth 16 "$WORK/z.pgm" ;;
    esac
  else json_skip Z1 imagemagick "ImageMagick not installed"; fi
done

# --- R1 ------------------------------------------------------------------------------------
# A synthetic 4928×3279 RGB photo stand-in: three differently scaled zone plates.
for i in 1 2 3; do
  "$R" render --scene zoneplate --param numax=0.0$((i + 2)) --size 4928x3279 --spp 1 --depth 8 --to pgm -o "$WORK/c$i.pgm"
done
if have vips; then
  vips bandjoin "$WORK/c1.pgm $WORK/c2.pgm $WORK/c3.pgm" "$WORK/r1.ppm"
else
  # Without vips: a grey PPM from one channel (fconv cannot join bands).
  "$BIN/fconv" "$WORK/c1.pgm" --to png -o "$WORK/c1.png"
  json_skip R1 setup "vips missing: R1 input is not RGB"; cp "$WORK/c1.pgm" "$WORK/r1.ppm"
fi
rm -f "$WORK"/c?.pgm
r1() {  # tool mode command...
  local tool=$1 mode=$2; shift 2
  timed "$@"
  if [ "$ok" -ne 1 ]; then json_skip R1 "$tool" "failed: $(head -c 200 "$WORK/err" | tr '\n"' ' ')"; return; fi
  printf '{"bench":"resample","case":"R1","tool":"%s","mode":"%s","seconds":%s,"cpu_seconds":%s,"peak_mb":%s}\n' "$tool" "$mode" "$secs" "$cpu" "$peak_mb"
  eval "r1_${tool}_${mode}=$secs r1_${tool}_${mode}_cpu=$cpu"
}
r1 resample codes "$R" resize "$WORK/r1.ppm" --size 852x567 --filter lanczos3 --colorspace codes --threads 2 -o "$WORK/o.ppm"
r1 resample linear "$R" resize "$WORK/r1.ppm" --size 852x567 --filter lanczos3 --threads 2 -o "$WORK/o.ppm"
r1 resample codes1thread "$R" resize "$WORK/r1.ppm" --size 852x567 --filter lanczos3 --colorspace codes --threads 1 -o "$WORK/o.ppm"
if have vips; then
  r1 vips codes vips resize "$WORK/r1.ppm" "$WORK/o.ppm" 0.172890 --vscale 0.172918 --kernel lanczos3
  r1 vips linear vips thumbnail "$WORK/r1.ppm" "$WORK/o.ppm" 852 --height 567 --size force --linear
else json_skip R1 vips "vips not installed (libvips-tools)"; fi
if [ -n "$IM" ]; then
  r1 imagemagick codes "$IM" "$WORK/r1.ppm" -filter Lanczos -resize '852x567!' "$WORK/o.ppm"
else json_skip R1 imagemagick "ImageMagick not installed"; fi
if have oiiotool; then
  RUNS=1 r1 oiiotool codes oiiotool "$WORK/r1.ppm" --resize 852x567 -o "$WORK/o.ppm"
else json_skip R1 oiiotool "oiiotool not installed (openimageio-tools)"; fi
ratio() { [ -n "${1:-}" ] && [ -n "${2:-}" ] && awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a / b }' || printf null; }
printf '{"bench":"resample","case":"R1","summary":true,"codes_vs_vips":%s,"codes_cpu_vs_vips":%s,"linear_vs_vips_codes":%s,"linear_vs_vips_linear":%s,"linear_cpu_vs_vips_linear":%s,"imagemagick_vs_resample":%s,"oiiotool_vs_resample":%s}\n' \
  "$(ratio "${r1_resample_codes:-}" "${r1_vips_codes:-}")" "$(ratio "${r1_resample_codes_cpu:-}" "${r1_vips_codes_cpu:-}")" \
  "$(ratio "${r1_resample_linear:-}" "${r1_vips_codes:-}")" \
  "$(ratio "${r1_resample_linear:-}" "${r1_vips_linear:-}")" "$(ratio "${r1_resample_linear_cpu:-}" "${r1_vips_linear_cpu:-}")" \
  "$(ratio "${r1_imagemagick_codes:-}" "${r1_resample_codes:-}")" \
  "$(ratio "${r1_oiiotool_codes:-}" "${r1_resample_codes:-}")"
rm -f "$WORK/r1.ppm"

# --- R2 ------------------------------------------------------------------------------------
"$R" render --scene zoneplate --param numax=0.02 --size 8192x8192 --spp 1 -o "$WORK/r2.pfm"
r2() {
  local tool=$1; shift
  timed "$@"
  if [ "$ok" -ne 1 ]; then json_skip R2 "$tool" "failed: $(head -c 200 "$WORK/err" | tr '\n"' ' ')"; return; fi
  printf '{"bench":"resample","case":"R2","tool":"%s","seconds":%s,"cpu_seconds":%s,"peak_mb":%s}\n' "$tool" "$secs" "$cpu" "$peak_mb"
  eval "r2_${tool}=$secs r2_${tool}_cpu=$cpu r2_${tool}_mb=$peak_mb"
}
r2 resample "$R" resize "$WORK/r2.pfm" --size 1024x1024 --filter mitchell --threads 2 -o "$WORK/o.pfm"
r2 resample1thread "$R" resize "$WORK/r2.pfm" --size 1024x1024 --filter mitchell --threads 1 -o "$WORK/o.pfm"
if have vips; then r2 vips vips resize "$WORK/r2.pfm" "$WORK/o.pfm" 0.125 --kernel mitchell
else json_skip R2 vips "vips not installed (libvips-tools)"; fi
printf '{"bench":"resample","case":"R2","summary":true,"seconds_vs_vips":%s,"cpu_vs_vips":%s,"peak_vs_vips":%s}\n' \
  "$(ratio "${r2_resample:-}" "${r2_vips:-}")" "$(ratio "${r2_resample_cpu:-}" "${r2_vips_cpu:-}")" \
  "$(ratio "${r2_resample_mb:-}" "${r2_vips_mb:-}")"
