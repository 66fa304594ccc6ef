#!/usr/bin/env bash
# facefit on a real, user-provided face model (none may be shipped). Opt-in:
#   FACEFIT_SFM=/path/sfm_shape_3448.bin        eos Surrey Face Model (shape only)
#   FACEFIT_SFM_MAP=/path/ibug_to_sfm.txt        optional: eos's iBUG landmark map
#   FACEFIT_BFM2009_NPZ=/path/bfm2009.npz        Basel 2009 as .npz (see mmb(5)), in µm
# Skipped (exit 77) when none is set.
. "$(dirname "$0")/lib.sh"
F="$FEST_BIN/facefit"
if [ -z "${FACEFIT_SFM:-}" ] && [ -z "${FACEFIT_BFM2009_NPZ:-}" ]; then
  echo "skipped: set FACEFIT_SFM or FACEFIT_BFM2009_NPZ to a real model file" >&2
  exit 77
fi

if [ -n "${FACEFIT_SFM:-}" ]; then
  case_ "Surrey Face Model: convert, 3448 vertices, 63 components"
  map_args=()
  [ -n "${FACEFIT_SFM_MAP:-}" ] && map_args=(--landmarks "$FACEFIT_SFM_MAP")
  run facefit convert --from eos "$FACEFIT_SFM" "${map_args[@]}" -o "$WORK/sfm.mmb"
  expect_status 0
  run facefit info -m "$WORK/sfm.mmb"
  expect_json '.points' '3448'
  expect_json '.components' '63'
  check "mean face 130-170 mm wide" jq -e '(.mean_bbox.max[0] - .mean_bbox.min[0]) as $w | $w > 130 and $w < 170' "$out"
  case_ "SFM: a random face's 50 landmarks fitted; mesh 130-170 mm wide"
  "$F" sample -m "$WORK/sfm.mmb" --random 1 --seed 4 -o "$WORK/face.ply"
  if [ -n "${FACEFIT_SFM_MAP:-}" ]; then
    awk -F'=' '/^\[landmark_mappings\]/ {on=1; next} /^\[/ {on=0} on && NF==2 {gsub(/[ "\t]/, "", $1); split($2, v, "#"); gsub(/ /, "", v[1]); print $1 "\t" v[1]}' \
      "$FACEFIT_SFM_MAP" | { echo "name	vertex"; cat; } >"$WORK/set.tsv"
  else
    awk 'BEGIN {print "name\tvertex"; for (i = 0; i < 50; i++) print "v" i "\t" i * 67}' >"$WORK/set.tsv"
  fi
  "$F" project --mesh "$WORK/face.ply" --vertices "$WORK/set.tsv" --by-vertex >"$WORK/lm.tsv"
  run facefit fit -m "$WORK/sfm.mmb" --landmarks "$WORK/lm.tsv" --eta auto=evidence -o "$WORK/fit.ply"
  expect_status 0
  run fconv --info "$WORK/fit.ply"
  check "fitted mesh 130-170 mm wide" jq -e '(.bbox.max[0] - .bbox.min[0]) as $w | $w > 130 and $w < 170' "$out"
fi

if [ -n "${FACEFIT_BFM2009_NPZ:-}" ]; then
  case_ "Basel 2009 via .npz (µm -> mm): the η sweep of figs. 1.3-1.4 on faces sampled from it, small"
  run facefit convert --from npz "$FACEFIT_BFM2009_NPZ" --scale 0.001 -o "$WORK/bfm.mmb"
  expect_status 0
  run facefit info -m "$WORK/bfm.mmb"
  expect_json '.points' '53490'
  "$F" sample -m "$WORK/bfm.mmb" --random 30 --seed 1 -o "$WORK/bfm_faces"
  ls "$WORK"/bfm_faces/sample0{01..20}.ply >"$WORK/train.txt"
  ls "$WORK"/bfm_faces/sample0{21..30}.ply >"$WORK/test.txt"
  run facefit build -o "$WORK/b19.mmb" --list "$WORK/train.txt"
  expect_status 0
  awk 'BEGIN {print "name\tvertex"; for (i = 0; i < 50; i++) print "v" i "\t" i * 1069}' >"$WORK/set50.tsv"
  run facefit sweep -m "$WORK/b19.mmb" --faces "$WORK/test.txt" --vertices "$WORK/set50.tsv" --summary
  expect_status 0
  check "interior optimum of E_full over eta" awk -F'\t' 'NR>1 {if (min=="" || $9<min) {min=$9; at=NR}} END {exit !(at>2 && at<NR)}' "$out"
fi
finish
