#!/usr/bin/env bash
# mutate.sh -- the zzuf sweep of issue 31, run by hand (not part of the suite).
#
# For every input kind fest reads (VTU, legacy VTK, PLY, OBJ, OFF, STL, Draco, PNG, JPEG, PFM,
# EXR, TIFF, NIfTI, NRRD, MetaImage, .ebm, .tlp, .ltx, .mmb, scene JSON) it takes seed
# files (from tests/data/ and small ones the tools write themselves), makes N variants of
# them -- zzuf bit flips at ratios 1e-5 .. 0.05 with a fixed seed per variant, and every
# 8th variant a truncation -- and runs the tools that read that kind on each variant
# under `timeout`.  A variant counts under a column when one of its commands:
#
#   signal     died by a signal (exit > 128 other than the timeout's), or printed a
#              sanitizer / abort text
#   hang       ran past --timeout (exit 124 or 137)
#   wrongcode  exited with something other than 0, 3 (bad input) or 4 (I/O), or exited 0
#              with an empty or missing output
#   partial    left its -o file behind after a non-zero exit
#   rawbytes   printed control characters or bytes that are not UTF-8 on stderr, or a
#              stderr line over 300 bytes (quoted input)
#   libtext    let a library's own words through: "[json.exception", what():, std::,
#              VTK's "ERROR: In /..." and the like
#   multiline  printed more than one stderr line on a failing exit
#
# Mutated files that came out identical to their seed are counted under "same" and not
# run.  Every variant with a finding is copied to OUT/fail/<kind>/ with each command's
# stderr; OUT/summary.tsv holds one line per command run with the command that remakes
# the variant (zzuf -s SEED -r RATIO < seed, or head -c LEN < seed); OUT/table.txt is the
# table printed at the end.
#
# Usage:
#   FEST_BIN=build/bin tests/fuzz/mutate.sh [--quick] [-n N] [-j JOBS] [-t SECONDS]
#        [--mem MB] [-o OUTDIR] [KIND ...]
#   nice -n 10 tests/fuzz/mutate.sh --quick            # 30 variants per kind
#   tests/fuzz/mutate.sh -n 300 vtu vtk json           # three kinds, full count
#
# Needs zzuf (scripts/install-deps.sh --test-tools).  Memory per command is capped with
# `ulimit -v` (--mem, default 4096 MB) so that a header asking for 100 GB fails inside
# the tool instead of taking the machine; the run never touches FEST_BIN.
set -u

ALL_KINDS="vtu vtuedit vtk ply obj off stl drc png jpeg pfm exr tiff nifti nrrd mha ebm tlp ltx mmb json"
RATIOS=(1e-5 3e-5 1e-4 3e-4 1e-3 3e-3 0.01 0.02 0.05)
TRUNC_PERCENT=(0 1 3 10 25 50 75 90 97 99)

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

# ---------------------------------------------------------------------------------------
# Worker: one variant.  Invoked as `mutate.sh __one KIND INDEX` by xargs, with the
# settings in the environment.
# ---------------------------------------------------------------------------------------
commands_for() { # kind -> lines "name<TAB>command" with {in} and {out} placeholders
  # (exit codes taken as right for bad input: 0, 3, 4, and 1 for `terrainlod verify`,
  # whose page says 1 = a check failed)
  local B=$FEST_BIN
  case $1 in
    vtu|vtuedit)
          printf '%s\t%s\n' info "$B/fconv --info {in}" tovtk "$B/fconv {in} --to vtk -o {out}.vtk" \
            classify "$B/lemtrace classify {in}" \
            trace "$B/lemtrace trace {in} --threads 1 --seed-point 0.3,0.4,0.5 -o {out}.csv" ;;
    vtk)  printf '%s\t%s\n' info "$B/fconv --info {in}" tovtu "$B/fconv {in} --to vtu -o {out}.vtu" \
            classify "$B/lemtrace classify {in}" ;;
    ply)  printf '%s\t%s\n' info "$B/fconv --info {in}" toobj "$B/fconv {in} --to obj -o {out}.obj" \
            ebcode "$B/ebcode {in} -o {out}.ebm" ;;
    obj|off|stl)
          printf '%s\t%s\n' info "$B/fconv --info {in}" toply "$B/fconv {in} --to ply -o {out}.ply" ;;
    drc)  printf '%s\t%s\n' info "$B/fconv --info {in}" toply "$B/fconv {in} --to ply -o {out}.ply" \
            ebdecode "$B/ebdecode {in} -o {out}.ply" ;;
    png|exr|tiff|pfm)   # TIFF holds every sample type fest reads (8/16-bit, float)
          printf '%s\t%s\n' info "$B/fconv --info {in}" totiff "$B/fconv {in} --to tiff -o {out}.tiff" ;;
    jpeg) printf '%s\t%s\n' info "$B/fconv --info {in}" topng "$B/fconv {in} --to png -o {out}.png" \
            resize "$B/resample resize {in} --width 7 -o {out}.jpg" ;;
    nifti|mha)
          printf '%s\t%s\n' info "$B/fconv --info {in}" tonrrd "$B/fconv {in} --to nrrd -o {out}.nrrd" ;;
    nrrd) printf '%s\t%s\n' info "$B/fconv --info {in}" tonii "$B/fconv {in} --to nii -o {out}.nii" ;;
    ebm)  printf '%s\t%s\n' ebdecode "$B/ebdecode {in} -o {out}.ply" ;;
    tlp)  printf '%s\t%s\n' stats "$B/terrainlod stats {in}" verify "$B/terrainlod verify {in}" \
            decode "$B/terrainlod decode {in} --tile 0/0/0 -o {out}.ply" ;;
    ltx)  printf '%s\t%s\n' info "$B/brdffit info {in}" ;;
    mmb)  printf '%s\t%s\n' info "$B/facefit info -m {in}" \
            sample "$B/facefit sample -m {in} -o {out}.ply" ;;
    json) printf '%s\t%s\n' solve "$B/radiosity solve {in} --no-mesh --levels 0 --ff analytic --tol 0.5 --max-shots 5 -o {out}.ply" ;;
  esac
}

esc() { # stdin -> one line, control and non-ASCII bytes as \xNN, at most $1 bytes
  LC_ALL=C od -An -v -tu1 | tr -s ' \n' '  ' | awk -v max="$1" '{
    s = ""; for (i = 1; i <= NF && length(s) < max; i++) {
      c = $i + 0
      if (c == 10) s = s "\\n"; else if (c == 9) s = s "\\t";
      else if (c == 92) s = s "\\\\";
      else if (c < 32 || c > 126) s = s sprintf("\\x%02x", c); else s = s sprintf("%c", c)
    } print s }'
}

run_one() {
  local kind=$1 i=$2
  local seeds=("$OUT/seeds/$kind"/*)
  local n=${#seeds[@]}
  local seed=${seeds[$((i % n))]}
  local ext=${seed##*.}
  local w="$OUT/work/$kind/$i"
  mkdir -p "$w"
  local v="$w/in.$ext" mut repro
  local rel=${seed#"$OUT/"}
  if [ "$kind" = vtuedit ] && (( i < n )); then
    cp "$seed" "$v"     # the hand edit itself, unmutated
    mut="edit" repro="cp $rel"
  elif (( i % 8 == 7 )); then
    local size pct len
    size=$(stat -c %s "$seed")
    pct=${TRUNC_PERCENT[$(( (i / 8) % ${#TRUNC_PERCENT[@]} ))]}
    len=$(( size * pct / 100 ))
    (( len >= size )) && len=$(( size - 1 ))
    head -c "$len" "$seed" > "$v"
    mut="trunc:$len" repro="head -c $len < $rel"
  else
    local r=${RATIOS[$(( (i / n) % ${#RATIOS[@]} ))]}
    # at least one expected bit flip: a 50-byte PFM at 1e-5 would never change
    r=$(awk -v r="$r" -v size="$(stat -c %s "$seed")" 'BEGIN { m = 1 / (8 * (size > 0 ? size : 1)); if (r < m) r = m; printf "%.3g", r }')
    # A small file at a small ratio often comes out unchanged: try further zzuf seeds
    # (i + 100000 k) so that each variant differs from its seed at the asked ratio.
    local s=$i k
    for ((k = 0; k < 20; k++)); do
      s=$(( i + 100000 * k ))
      zzuf -s "$s" -r "$r" < "$seed" > "$v"
      cmp -s "$v" "$seed" || break
    done
    mut="zzuf:s=$s:r=$r" repro="zzuf -s $s -r $r < $rel"
  fi
  local res="$w/result.tsv"
  : > "$res"
  if [ "$mut" != edit ] && cmp -s "$v" "$seed"; then
    printf '%s\t%s\t%s\t%s\t-\tsame\t\t\t%s\n' "$kind" "$i" "$rel" "$mut" "$repro" > "$res"
    rm -f "$v"; return 0
  fi
  local any=0 name cmd
  while IFS=$'\t' read -r name cmd; do
    local c=${cmd//\{in\}/$v}
    c=${c//\{out\}/$w/out_$name}
    local outfile=""
    [[ $cmd == *'{out}'* ]] && outfile=$(sed -n 's/.*-o \([^ ]*\).*/\1/p' <<<"$c")
    local err="$w/$name.err" so="$w/$name.out" rc
    { ( ulimit -v $(( MEM_MB * 1024 )) 2>/dev/null
        cd "$w" && exec timeout -k 2 "$TIMEOUT" $c ) > "$so" 2> "$err" < /dev/null; } 2> /dev/null
    rc=$?   # (the braces keep bash's own "Segmentation fault" line out of the run's output)
    local flags=()
    if (( rc == 124 || rc == 137 )); then flags+=(hang)
    elif (( rc > 128 )) || grep -qaE 'AddressSanitizer|runtime error:|LeakSanitizer|terminate called|Segmentation fault|Aborted|core dumped|stack smashing' "$err"; then flags+=(signal)
    elif (( rc != 0 && rc != 3 && rc != 4 )) && ! [[ $name == verify && $rc == 1 ]]; then flags+=(wrongcode)
    elif (( rc == 0 )); then
      if [ -n "$outfile" ]; then [ -s "$outfile" ] || flags+=(wrongcode)
      else [ -s "$so" ] || flags+=(wrongcode); fi
    fi
    if (( rc != 0 )) && [ -n "$outfile" ] && [ -e "$outfile" ]; then flags+=(partial); fi
    if LC_ALL=C grep -qaP '[\x00-\x08\x0b-\x1f\x7f]' "$err" || ! iconv -f UTF-8 -t UTF-8 "$err" > /dev/null 2>&1 \
       || LC_ALL=C awk 'length > 300 { f = 1 } END { exit !f }' "$err"; then flags+=(rawbytes); fi
    if grep -qaE '\[json\.exception|what\(\)|std::|basic_string|vector::|bad_alloc|stoi|stod|ERROR: In /|Warning: In /|vtk[A-Z][A-Za-z]+(Reader|Parser)|Iex::|cereal::|TIFFRead|libpng error|Supported types are|Error reading uncompressed|Error parsing XML|Cannot read (ascii|binary|appended) data|in piece [0-9]|may be too short|syntax error while parsing|last read: ' "$err"; then flags+=(libtext); fi
    if (( rc != 0 )) && (( $(wc -l < "$err") > 1 )); then flags+=(multiline); fi
    local f="${flags[*]}"
    (( ${#flags[@]} )) && any=1
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$kind" "$i" "$rel" "$mut" "$name" "$rc" "${f// /,}" \
      "$(head -c 2000 "$err" | esc 240)" "$repro" >> "$res"
  done < <(commands_for "$kind")
  if (( any )); then
    mkdir -p "$OUT/fail/$kind"
    cp "$v" "$OUT/fail/$kind/$i.$ext"
    for e in "$w"/*.err; do cp "$e" "$OUT/fail/$kind/$i.$(basename "$e")"; done
  fi
  find "$w" -mindepth 1 ! -name result.tsv -delete
}

if [ "${1:-}" = __one ]; then run_one "$2" "$3"; exit 0; fi

# ---------------------------------------------------------------------------------------
# Driver
# ---------------------------------------------------------------------------------------
N=300 JOBS=$(nproc) TIMEOUT=10 MEM_MB=4096 OUT=mutate-out KINDS=()
while [ $# -gt 0 ]; do
  case $1 in
    --quick) N=30 ;;
    -n) N=$2; shift ;;
    -j) JOBS=$2; shift ;;
    -t|--timeout) TIMEOUT=$2; shift ;;
    --mem) MEM_MB=$2; shift ;;
    -o) OUT=$2; shift ;;
    -h|--help) sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "mutate.sh: error: unknown option $1" >&2; exit 2 ;;
    *) KINDS+=("$1") ;;
  esac
  shift
done
[ ${#KINDS[@]} -eq 0 ] && read -r -a KINDS <<<"$ALL_KINDS"
FEST_BIN=$(cd "${FEST_BIN:-$root/build/bin}" 2>/dev/null && pwd) \
  || { echo "mutate.sh: error: FEST_BIN (${FEST_BIN:-build/bin}) is not a folder" >&2; exit 2; }
command -v zzuf > /dev/null || { echo "mutate.sh: error: zzuf not found (apt-get install zzuf)" >&2; exit 2; }
for k in "${KINDS[@]}"; do
  [[ " $ALL_KINDS " == *" $k "* ]] || { echo "mutate.sh: error: unknown kind $k (kinds: $ALL_KINDS)" >&2; exit 2; }
done
mkdir -p "$OUT" && OUT=$(cd "$OUT" && pwd)
rm -rf "$OUT/work" "$OUT/fail" "$OUT/seeds"
mkdir -p "$OUT/seeds" "$OUT/work"
export FEST_BIN OUT TIMEOUT MEM_MB

# Seeds: files from tests/data plus small files the tools write.  Each is checked to
# read cleanly (every command exits 0) before it is mutated.
D=$root/tests/data S=$OUT/seeds G=$OUT/gen B=$FEST_BIN
mkdir -p "$G"
mk() { mkdir -p "$S/$1"; }
add() { local k=$1; shift; mk "$k"; for f in "$@"; do [ -s "$f" ] && cp "$f" "$S/$k/"; done; }
q() { "$@" > /dev/null 2>&1; }
q "$B/lemtrace" gen rotation --n 2 -o "$G/rot_n2.vtu"
q "$B/lemtrace" gen helix --n 2 --hex -o "$G/helix_hex.vtu"
q "$B/lemtrace" gen saddle --n 2 --to vtk -o "$G/saddle.vtk"
q "$B/fconv" "$G/rot_n2.vtu" --to vtk --ascii -o "$G/rot_ascii.vtk"
add vtu "$D/dataset/rotating_tets.vtu" "$G/rot_n2.vtu" "$G/helix_hex.vtu"
add vtk "$G/saddle.vtk" "$G/rot_ascii.vtk"
# vtuedit: legal attribute values that no longer match the bytes, and broken offsets
# (issue 31's hand-made VTU cases), each tried as is, then mutated.
e=$S/vtuedit; mk vtuedit
if [ -s "$G/rot_n2.vtu" ]; then
  r=$G/rot_n2.vtu
  sed 's/header_type="UInt64"/header_type="UInt32"/' "$r" > "$e/header_uint32.vtu"
  sed 's/ header_type="UInt64"//' "$r" > "$e/header_default.vtu"
  sed 's/byte_order="LittleEndian"/byte_order="BigEndian"/' "$r" > "$e/big_endian.vtu"
  sed '0,/type="Float64" Name="velocity"/s//type="Float6x" Name="velocity"/' "$r" > "$e/type_typo.vtu"
  sed '0,/type="Float64" Name="velocity"/s//type="Int8" Name="velocity"/' "$r" > "$e/type_int8.vtu"
  sed 's/offset="785"  /offset="99999"/' "$r" > "$e/offset_past_end.vtu"
  sed 's/offset="785"  /offset="-785" /' "$r" > "$e/offset_negative.vtu"
  sed 's/NumberOfPoints="27"  /NumberOfPoints="2700"/' "$r" > "$e/points_too_many.vtu"
  sed 's/NumberOfCells="48"  /NumberOfCells="4800"/' "$r" > "$e/cells_too_many.vtu"
  # the first appended block's length (8 bytes after '_') set to 2^40
  python3 - "$r" "$e/block_length_huge.vtu" <<'PY'
import sys
b = open(sys.argv[1], 'rb').read(); i = b.index(b'_', b.index(b'<AppendedData')) + 1
open(sys.argv[2], 'wb').write(b[:i] + (1 << 40).to_bytes(8, 'little') + b[i + 8:])
PY
fi
q "$B/fconv" "$D/mesh/tetra_colors_normals.ply" --to ply -o "$G/tetra_bin.ply"
q "$B/fconv" "$D/mesh/cube_quads.off" --to ply --ascii -o "$G/cube_ascii.ply"
add ply "$D/mesh/tetra_colors_normals.ply" "$G/tetra_bin.ply" "$G/cube_ascii.ply"
q "$B/fconv" "$D/mesh/cube_quads.off" --to obj -o "$G/cube.obj"
add obj "$D/mesh/square_uv.obj" "$G/cube.obj"
add off "$D/mesh/cube_quads.off"
q "$B/fconv" "$D/mesh/cube_quads.off" --to stl --ascii -o "$G/cube_ascii.stl"
add stl "$D/mesh/triangle.stl" "$G/cube_ascii.stl"
q "$B/fconv" "$D/mesh/cube_quads.off" --to drc -o "$G/cube.drc"
q "$B/fconv" "$D/mesh/tetra_colors_normals.ply" --to drc --draco-bits 0 -o "$G/tetra.drc"
add drc "$G/cube.drc" "$G/tetra.drc"
q "$B/fconv" "$D/image/comments_ascii.pgm" --to png -o "$G/grey.png"
q "$B/fconv" "$D/image/pattern_raw.ppm" --to png -o "$G/colour.png"
add png "$G/grey.png" "$G/colour.png"
q "$B/fconv" "$D/image/comments_ascii.pgm" --to jpg -o "$G/grey.jpg"
q "$B/fconv" "$D/image/pattern_raw.ppm" --to jpg --quality 80 -o "$G/colour.jpg"
add jpeg "$G/grey.jpg" "$G/colour.jpg"
add pfm "$D/image/colour_little_endian.pfm" "$D/image/grey_big_endian.pfm"
q "$B/fconv" "$D/image/colour_little_endian.pfm" --to exr -o "$G/colour.exr"
q "$B/fconv" "$D/image/grey_little_endian.pfm" --to exr --half -o "$G/grey_half.exr"
add exr "$G/colour.exr" "$G/grey_half.exr"
q "$B/fconv" "$D/image/pattern_raw.ppm" --to tiff -o "$G/colour.tiff"
q "$B/fconv" "$D/image/colour_little_endian.pfm" --to tiff -o "$G/float.tiff"
add tiff "$G/colour.tiff" "$G/float.tiff"
add nifti "$D/volume/be_int16.nii" "$D/volume/scaled_uint8.nii"
q "$B/fconv" "$D/volume/msb_short.mha" --to nrrd -o "$G/raw.nrrd"
add nrrd "$D/volume/lps_ascii.nrrd" "$D/volume/gzip_uint16.nrrd" "$G/raw.nrrd"
add mha "$D/volume/msb_short.mha" "$D/volume/zlib_float.mha"
add ebm "$D/ebm/tetrahedron.ebm" "$D/ebm/tetrahedron_attributes_v2.ebm" "$D/ebm/eight_genus2_v2.ebm" \
  "$D/ebm/mushroom_hole.ebm"
add tlp "$D/terrainlod/tiny.tlp" "$D/terrainlod/tiny_hole.tlp"
add ltx "$D/brdffit/tiny.ltx"
add mmb "$D/facefit/seeds/tiny.mmb"
add json "$D/radiosity/cornell.json"
rm -rf "$G"

for k in "${KINDS[@]}"; do
  ls "$S/$k"/* > /dev/null 2>&1 || { echo "mutate.sh: error: no seed for $k (were the tools built?)" >&2; exit 1; }
  [ "$k" = vtuedit ] && continue   # its seeds are bad on purpose
  for f in "$S/$k"/*; do
    while IFS=$'\t' read -r name cmd; do
      c=${cmd//\{in\}/$f}; c=${c//\{out\}/$OUT/seedcheck}
      ( cd "$OUT" && timeout "$TIMEOUT" $c ) > /dev/null 2>&1
      rc=$?
      (( rc == 0 )) || echo "mutate.sh: warning: seed ${f#"$OUT/"} fails its own command '$name' (exit $rc)" >&2
      rm -f "$OUT"/seedcheck*
    done < <(commands_for "$k")
  done
done

echo "mutate.sh: ${#KINDS[@]} kinds x $N variants, $JOBS jobs, timeout ${TIMEOUT}s, FEST_BIN=$FEST_BIN" >&2
start=$(date +%s)
for k in "${KINDS[@]}"; do
  for ((i = 0; i < N; i++)); do echo "$k $i"; done
done | xargs -P "$JOBS" -n 2 "$0" __one
secs=$(( $(date +%s) - start ))

summary=$OUT/summary.tsv
printf 'kind\tvariant\tseed\tmutation\tcommand\texit\tfindings\tstderr\tremake\n' > "$summary"
for k in "${KINDS[@]}"; do
  find "$OUT/work/$k" -name result.tsv -print0 2>/dev/null | sort -zV | xargs -0 -r cat >> "$summary"
done
rm -rf "$OUT/work"

awk -F'\t' -v secs="$secs" '
  NR == 1 { next }
  { key = $1 SUBSEP $2
    if (!(key in seen)) { seen[key] = 1; var[$1]++; if (!($1 in order)) { order[$1] = ++nk; names[nk] = $1 } }
    if ($6 == "same") { same[$1]++; next }
    if ($7 == "") next
    n = split($7, fl, ",")
    for (j = 1; j <= n; j++) { fk = $1 SUBSEP $2 SUBSEP fl[j]; if (!(fk in hit)) { hit[fk] = 1; cnt[$1, fl[j]]++ } }
  }
  END {
    split("signal hang wrongcode partial rawbytes libtext multiline", cols, " ")
    printf "| %-8s | %8s | %4s | %7s | %5s | %10s | %8s | %9s | %12s | %9s |\n", "kind", "variants", "same", "signals", "hangs", "wrong code", "partial", "raw bytes", "library text", "multiline"
    printf "|----------|----------|------|---------|-------|------------|----------|-----------|--------------|-----------|\n"
    for (k = 1; k <= nk; k++) {
      K = names[k]; printf "| %-8s | %8d | %4d |", K, var[K], same[K]
      w[1] = 7; w[2] = 5; w[3] = 10; w[4] = 8; w[5] = 9; w[6] = 12; w[7] = 9
      for (c = 1; c <= 7; c++) { printf " %*d |", w[c], cnt[K, cols[c]]; tot[c] += cnt[K, cols[c]] }
      tv += var[K]; ts += same[K]; printf "\n"
    }
    printf "| %-8s | %8d | %4d |", "all", tv, ts
    for (c = 1; c <= 7; c++) printf " %*d |", w[c], tot[c]
    printf "\n\n%d variants in %d s\n", tv, secs
  }' "$summary" | tee "$OUT/table.txt"
# One example per kind and finding (the first variant), to read beside the table.
awk -F'\t' 'NR > 1 && $7 != "" && $6 != "same" { n = split($7, fl, ",")
    for (j = 1; j <= n; j++) if (!(($1, fl[j]) in seen)) { seen[$1, fl[j]] = 1
      printf "%s %s: %s %s (exit %s) %s\n   %s\n", $1, fl[j], $2, $5, $6, $4, substr($8, 1, 300) } }' \
  "$summary" > "$OUT/examples.txt"
echo "findings: $OUT/fail/<kind>/, one example per finding: $OUT/examples.txt," \
  "every command run: $summary" >&2
