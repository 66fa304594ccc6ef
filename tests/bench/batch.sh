#!/usr/bin/env bash
# Batch speed (issue 21): a Makefile over many small files run with `make -j2`, fest's tools
# through Makefile.inc against the field's command-line tools, each driven by a Makefile of
# the same shape (one rule per file, `mkdir -p` then one command) in the same run.
#
#   tests/bench/batch.sh [--files N] [--bin DIR] [--jobs J] [--tools LIST]
#
# defaults: 1000 files, build/bin, make -j2, every tool (LIST: comma-separated among fest,
# vips, netpbm, imagemagick, ctmconv, assimp). N = 1000 took 20 minutes on 2 cores at load 15;
# KEEP=1 keeps the temporary folder (its path is in the "inputs" line).
#
# Needs the real data of scripts/fetch-test-data.sh ($FEST_TESTDATA, default
# ~/.cache/fest/testdata; exit 77 without it) and python3. Inputs, made in a temporary
# folder that is removed at the end:
#   - N 512x384 photos, half JPEG (quality 90) and half PNG: crops (tests/bench/
#     batch_inputs.py) of five photographs scaled by `resample` (astronaut, Grace Hopper,
#     messi5, aloeL/aloeR), written by `fconv`;
#   - N binary PLY meshes of 300-3,900 vertices: ten CGAL demo meshes, each file rotated,
#     scaled and moved differently.
# Batches:
#   resize   all N photos -> 256x192 PNG, lanczos3: `resample resize` (Makefile.inc rule
#            $(FEST_OUT)/resized/%.png), `vips resize 0.5 --kernel lanczos3`, netpbm
#            (jpegtopnm|pngtopam | pamscale -filter=lanczos | pnmtopng), ImageMagick
#            (convert -filter Lanczos -resize 256x192).
#   convert  the N/2 JPEG photos -> PNG: `fconv` (Makefile.inc rule $(FEST_OUT)/%.png: %.jpg),
#            `vips copy`, netpbm (jpegtopnm | pnmtopng), ImageMagick convert.
#   ply2off  all N meshes PLY -> OFF: `fconv` (Makefile.inc rule $(FEST_OUT)/%.off: %.ply),
#            `ctmconv` (openctm-tools), `assimp export` (assimp-utils; it cannot write OFF,
#            so it writes OBJ: the output is marked "to":"obj").
# Fairness on a machine whose load changes: each batch runs in ten slices of its inputs,
# the tools taking turns slice by slice (tool A slice 0, tool B slice 0, ..., then B first).
# One JSON line per (batch, tool) on standard output: wall seconds of `make -jJ` (summed
# over the slices), files/s,
# CPU ms per file (user + system of the whole make tree: what a loaded machine disturbs
# least), peak RSS (GNU time's %M of make: the largest process of the make tree, make included),
# output megabytes. A tool that is not installed gets a "skipped" line; a batch whose
# outputs are missing or wrong gets a "failed" line. Competitors are Debian packages
# (scripts/install-deps.sh, TEST_TOOL_PKGS): libvips-tools, netpbm, imagemagick,
# openctm-tools, assimp-utils. Timings on a shared machine are noise: read the figures,
# never fail on them.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
N=1000 BIN="$root/build/bin" JOBS=2 TOOLS=",fest,vips,netpbm,imagemagick,ctmconv,assimp,"
while [ $# -gt 0 ]; do
  case $1 in
    --files) N=$2; shift ;;
    --bin) BIN=$2; shift ;;
    --jobs) JOBS=$2; shift ;;
    --tools) TOOLS=",$2,"; shift ;;
    -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "batch.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case $N in '' | *[!0-9]* | 0 | 1 | ?????*) echo "batch.sh: --files needs a whole number from 2 to 9999" >&2; exit 2 ;; esac
BIN=$(cd "$BIN" 2>/dev/null && pwd) || { echo "batch.sh: no folder $BIN" >&2; exit 2; }
for t in resample fconv; do
  [ -x "$BIN/$t" ] || { echo "batch.sh: no $BIN/$t (build the resample and fconv targets)" >&2; exit 2; }
done
: "${FEST_TESTDATA:=${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}"
D=$FEST_TESTDATA
PHOTOS="faces/astronaut.png faces/grace_hopper.jpg faces/messi5.jpg images/aloeL.jpg images/aloeR.jpg"
MESHES="eight hand head mushroom blobby bones elephant cow knot1 femur"
for f in $PHOTOS; do [ -f "$D/$f" ] || { echo "batch.sh: skipped: no $D/$f (run scripts/fetch-test-data.sh)" >&2; exit 77; }; done
for m in $MESHES; do [ -f "$D/meshes/$m.off" ] || { echo "batch.sh: skipped: no $D/meshes/$m.off (run scripts/fetch-test-data.sh)" >&2; exit 77; }; done
command -v python3 >/dev/null || { echo "batch.sh: skipped: python3 is needed to make the inputs" >&2; exit 77; }
[ -x /usr/bin/time ] || { echo "batch.sh: skipped: GNU time (/usr/bin/time) is needed" >&2; exit 77; }

WORK=$(mktemp -d "${TMPDIR:-/tmp}/fest-batch.XXXXXX")
trap '[ -n "${KEEP:-}" ] || rm -rf "$WORK"' EXIT
IN=$WORK/in MK=$WORK/mk OUT=$WORK/out
mkdir -p "$WORK/src" "$IN/img" "$IN/mesh" "$MK" "$OUT"
die() { echo "batch.sh: $*" >&2; exit 1; }

# --- inputs ---------------------------------------------------------------------------
# Sources of the crops, all at least 512x384: the photos scaled by resample (lanczos3).
src=0
scale_photo() {  # photo scale
  src=$((src + 1))
  "$BIN/resample" resize "$D/$1" --scale "$2" --filter lanczos3 --to ppm -o "$WORK/src/s$src.ppm" ||
    die "could not scale $1"
}
scale_photo faces/astronaut.png 1.5; scale_photo faces/astronaut.png 2
scale_photo faces/grace_hopper.jpg 1.5; scale_photo faces/grace_hopper.jpg 2
scale_photo faces/messi5.jpg 1.5; scale_photo faces/messi5.jpg 2
scale_photo images/aloeL.jpg 1; scale_photo images/aloeL.jpg 0.6
scale_photo images/aloeR.jpg 1; scale_photo images/aloeR.jpg 0.6
mkdir -p "$WORK/crops"
python3 "$here/batch_inputs.py" crops "$N" "$WORK/crops" "$WORK"/src/s*.ppm || die "could not crop the photos"
rm -rf "$WORK/src"
# even crops -> PNG, odd -> JPEG (quality 90), written by fconv, JOBS at a time
targets=""
for ((k = 0; k < N; k++)); do targets+=" $IN/img/$(printf 'img%04d' "$k").$( ((k % 2)) && echo jpg || echo png)"; done
cat >"$MK/inputs.mk" <<EOF
all:$targets
$IN/img/%.png: $WORK/crops/%.ppm ; @$BIN/fconv \$< -o \$@
$IN/img/%.jpg: $WORK/crops/%.ppm ; @$BIN/fconv --quality 90 \$< -o \$@
EOF
make -s -j"$JOBS" -f "$MK/inputs.mk" all || die "could not encode the photos"
rm -rf "$WORK/crops"
meshes=()
for m in $MESHES; do meshes+=("$D/meshes/$m.off"); done
python3 "$here/batch_inputs.py" meshes "$N" "$IN/mesh" "${meshes[@]}" || die "could not make the meshes"
n_img=$(find "$IN/img" -name '*.png' -o -name '*.jpg' | wc -l)
n_jpg=$(find "$IN/img" -name '*.jpg' | wc -l)
n_mesh=$(find "$IN/mesh" -name '*.ply' | wc -l)
[ "$n_img" -eq "$N" ] && [ "$n_mesh" -eq "$N" ] || die "made $n_img photos and $n_mesh meshes, not $N"
printf '{"bench":"batch","inputs":true,"photos":%d,"jpeg":%d,"png":%d,"photo_mb":%.1f,"meshes":%d,"mesh_mb":%.1f,"jobs":%d,"load1":%s,"dir":"%s"}\n' \
  "$n_img" "$n_jpg" "$((n_img - n_jpg))" "$(du -sk "$IN/img" | awk '{print $1 / 1024}')" "$n_mesh" \
  "$(du -sk "$IN/mesh" | awk '{print $1 / 1024}')" "$JOBS" "$(cut -d' ' -f1 /proc/loadavg)" "$WORK"

# --- the batches ----------------------------------------------------------------------
IM=""  # ImageMagick's own binary (a `convert` in PATH may be a wrapper script)
for c in magick convert-im6.q16 convert; do
  if command -v "$c" >/dev/null 2>&1 && "$c" -version 2>/dev/null | grep -q ImageMagick; then IM=$(command -v "$c"); break; fi
done
have() { command -v "$1" >/dev/null 2>&1; }
want() { [[ $TOOLS == *",$1,"* ]]; }

# Every batch's Makefile starts with head_mk: its inputs are the files whose number
# matches $(P) (a glob of four digits, default all), so one Makefile serves every slice.
head_mk() {  # batch tool
  printf 'OUT := %s\nP ?= ????\n' "$OUT/$2"
  printf 'IMGS := $(wildcard img/img$(P).png img/img$(P).jpg)\nJPGS := $(wildcard img/img$(P).jpg)\nPLYS := $(wildcard mesh/mesh$(P).ply)\n'
}
json() { printf '{"bench":"batch","batch":"%s","tool":"%s",%s}\n' "$1" "$2" "$3"; }
skip() { json "$1" "$2" "\"skipped\":\"$3\""; }

# batch BATCH FILES CHECK TOOL...: runs each tool's $MK/BATCH-TOOL.mk from $IN over ten
# slices of the inputs (file numbers ??0? .. ??9?), the tools taking turns slice by slice
# with the first one rotating, so a load that changes during the run falls on all tools
# alike; each tool's times are summed over its slices. make -k: a tool that crashes on a
# few inputs is timed over all of them and the crashes are counted ("failed_files").
# CHECK is a command given one output file (exit 0 when it is right).
batch() {
  local batch=$1 files=$2 check=$3; shift 3
  local tools=("$@") n=$# k i t s m u y made first extra
  [ "$n" -gt 0 ] || return 0
  local -A secs peak cpu
  for t in "${tools[@]}"; do rm -rf "${OUT:?}/$t"; : >"$WORK/err-$t"; secs[$t]=0 peak[$t]=0 cpu[$t]=0; done
  for ((k = 0; k < 10; k++)); do
    for ((i = 0; i < n; i++)); do
      t=${tools[$(((i + k) % n))]}
      /usr/bin/time -f "%e %M %U %S" -o "$WORK/time" make -k -s -j"$JOBS" -C "$IN" -f "$MK/$batch-$t.mk" P="??$k?" all \
        >/dev/null 2>>"$WORK/err-$t"
      read -r s m u y < <(tail -n 1 "$WORK/time")
      secs[$t]=$(awk -v a="${secs[$t]}" -v b="$s" 'BEGIN { print a + b }')
      cpu[$t]=$(awk -v a="${cpu[$t]}" -v b="$u" -v c="$y" 'BEGIN { print a + b + c }')
      [ "$m" -gt "${peak[$t]}" ] && peak[$t]=$m
    done
  done
  for t in "${tools[@]}"; do
    made=$(find "$OUT/$t" -type f 2>/dev/null | wc -l)
    first=$(find "$OUT/$t" -type f 2>/dev/null | sort | head -n 1)
    if [ "$made" -eq 0 ] || [ "$made" -gt "$files" ] || ! $check "$first"; then
      json "$batch" "$t" "\"failed\":\"$made of $files outputs, or a wrong one: ${first:-none}; $(head -c 200 "$WORK/err-$t" | tr '\n"\\' '   ')\""
      continue
    fi
    extra=""
    [ "$t" = assimp ] && extra=',"to":"obj"'
    [ "$made" -lt "$files" ] && extra+=$(printf ',"failed_files":%d,"first_error":"%s"' "$((files - made))" \
      "$(grep -m1 -i 'error\|fault' "$WORK/err-$t" | head -c 200 | tr '"\\' '  ')")
    json "$batch" "$t" "$(printf '"files":%d,"seconds":%.2f,"files_per_s":%.1f,"cpu_ms_per_file":%.1f,"peak_rss_mb":%.1f,"out_mb":%.1f%s' \
      "$files" "${secs[$t]}" "$(awk -v n="$files" -v s="${secs[$t]}" 'BEGIN { print (s > 0 ? n / s : 0) }')" \
      "$(awk -v n="$files" -v c="${cpu[$t]}" 'BEGIN { print 1000 * c / n }')" \
      "$(awk -v k="${peak[$t]}" 'BEGIN { print k / 1024 }')" "$(du -sk "$OUT/$t" | awk '{print $1 / 1024}')" "$extra")"
  done
}
# The outputs are checked with fconv --info (an independent reader would be better, but
# each competitor's output is read by fest here, and fest's own by the same code).
is_256x192() { [ "$("$BIN/fconv" --info "$1" 2>/dev/null | jq -c '[.width,.height]' 2>/dev/null)" = "[256,192]" ]; }
is_512x384() { [ "$("$BIN/fconv" --info "$1" 2>/dev/null | jq -c '[.width,.height]' 2>/dev/null)" = "[512,384]" ]; }
is_mesh() {  # the same number of faces as the input of the same name
  local a b
  a=$("$BIN/fconv" --info "$1" 2>/dev/null | jq .faces 2>/dev/null)
  b=$("$BIN/fconv" --info "$IN/mesh/$(basename "${1%.*}").ply" 2>/dev/null | jq .faces 2>/dev/null)
  [ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" != 0 ]
}
have jq || { is_256x192() { [ -s "$1" ]; }; is_512x384() { [ -s "$1" ]; }; is_mesh() { [ -s "$1" ]; }; }

# Warm every tool's binary and libraries once, so no batch pays a cold start.
for t in "$BIN/resample" "$BIN/fconv" vips "$IM" jpegtopnm pamscale pnmtopng ctmconv assimp; do
  [ -n "$t" ] && have "$t" && "$t" --version >/dev/null 2>&1
done

# resize ------------------------------------------------------------------------------
{ head_mk resize fest; printf 'FEST_BIN := %s\nFEST_OUT := $(OUT)\ninclude %s/Makefile.inc\n' "$BIN" "$root"
  printf 'all: $(patsubst %%,$(FEST_OUT)/resized/%%.png,$(basename $(IMGS)))\n'; } >"$MK/resize-fest.mk"
tools=(); want fest && tools+=(fest)
if ! want vips; then :; elif have vips; then
  { head_mk resize vips; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(IMGS)))\n'
    printf '$(OUT)/%%.png: %%.%s ; @mkdir -p $(@D) && vips resize $< $@ 0.5 --kernel lanczos3\n' png jpg; } >"$MK/resize-vips.mk"
  tools+=(vips)
else skip resize vips "vips not installed (libvips-tools)"; fi
if ! want netpbm; then :; elif have jpegtopnm && have pamscale && have pnmtopng; then
  { head_mk resize netpbm; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(IMGS)))\n'
    printf '$(OUT)/%%.png: %%.%s ; @mkdir -p $(@D) && %s -quiet $< | pamscale -quiet -width 256 -height 192 -filter=lanczos | pnmtopng -quiet >$@\n' \
      png pngtopam jpg jpegtopnm; } >"$MK/resize-netpbm.mk"
  tools+=(netpbm)
else skip resize netpbm "netpbm not installed"; fi
if ! want imagemagick; then :; elif [ -n "$IM" ]; then
  { head_mk resize imagemagick; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(IMGS)))\n'
    printf '$(OUT)/%%.png: %%.%s ; @mkdir -p $(@D) && %s $< -filter Lanczos -resize 256x192 $@\n' png "$IM" jpg "$IM"; } >"$MK/resize-imagemagick.mk"
  tools+=(imagemagick)
else skip resize imagemagick "ImageMagick not installed"; fi
batch resize "$N" is_256x192 "${tools[@]}"

# convert -----------------------------------------------------------------------------
{ head_mk convert fest; printf 'FEST_BIN := %s\nFEST_OUT := $(OUT)\ninclude %s/Makefile.inc\n' "$BIN" "$root"
  printf 'all: $(patsubst %%,$(FEST_OUT)/%%.png,$(basename $(JPGS)))\n'; } >"$MK/convert-fest.mk"
tools=(); want fest && tools+=(fest)
if ! want vips; then :; elif have vips; then
  { head_mk convert vips; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(JPGS)))\n'
    printf '$(OUT)/%%.png: %%.jpg ; @mkdir -p $(@D) && vips copy $< $@\n'; } >"$MK/convert-vips.mk"
  tools+=(vips)
else skip convert vips "vips not installed (libvips-tools)"; fi
if ! want netpbm; then :; elif have jpegtopnm && have pnmtopng; then
  { head_mk convert netpbm; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(JPGS)))\n'
    printf '$(OUT)/%%.png: %%.jpg ; @mkdir -p $(@D) && jpegtopnm -quiet $< | pnmtopng -quiet >$@\n'; } >"$MK/convert-netpbm.mk"
  tools+=(netpbm)
else skip convert netpbm "netpbm not installed"; fi
if ! want imagemagick; then :; elif [ -n "$IM" ]; then
  { head_mk convert imagemagick; printf 'all: $(patsubst %%,$(OUT)/%%.png,$(basename $(JPGS)))\n'
    printf '$(OUT)/%%.png: %%.jpg ; @mkdir -p $(@D) && %s $< $@\n' "$IM"; } >"$MK/convert-imagemagick.mk"
  tools+=(imagemagick)
else skip convert imagemagick "ImageMagick not installed"; fi
batch convert "$n_jpg" is_512x384 "${tools[@]}"

# ply2off -----------------------------------------------------------------------------
{ head_mk ply2off fest; printf 'FEST_BIN := %s\nFEST_OUT := $(OUT)\ninclude %s/Makefile.inc\n' "$BIN" "$root"
  printf 'all: $(patsubst %%.ply,$(FEST_OUT)/%%.off,$(PLYS))\n'; } >"$MK/ply2off-fest.mk"
tools=(); want fest && tools+=(fest)
if ! want ctmconv; then :; elif have ctmconv; then
  { head_mk ply2off ctmconv; printf 'all: $(patsubst %%.ply,$(OUT)/%%.off,$(PLYS))\n'
    printf '$(OUT)/%%.off: %%.ply ; @mkdir -p $(@D) && ctmconv $< $@ >/dev/null\n'; } >"$MK/ply2off-ctmconv.mk"
  tools+=(ctmconv)
else skip ply2off ctmconv "ctmconv not installed (openctm-tools)"; fi
if ! want assimp; then :; elif have assimp; then
  { head_mk ply2off assimp; printf 'all: $(patsubst %%.ply,$(OUT)/%%.obj,$(PLYS))\n'
    printf '$(OUT)/%%.obj: %%.ply ; @mkdir -p $(@D) && assimp export $< $@ -fobjnomtl >/dev/null\n'; } >"$MK/ply2off-assimp.mk"
  tools+=(assimp)
else skip ply2off assimp "assimp not installed (assimp-utils)"; fi
batch ply2off "$N" is_mesh "${tools[@]}"
