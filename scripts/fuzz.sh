#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each for SECONDS (default 600).
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_mesh fuzz_image_header fuzz_volume fuzz_mgh fuzz_json fuzz_clers fuzz_ebm fuzz_camera_json
  fuzz_image_stream fuzz_patnet fuzz_vw fuzz_radiosity_scene fuzz_volume_source fuzz_softobj fuzz_lbm_case fuzz_ffd_lattice fuzz_v4l2_frame fuzz_feshape_xyz
  fuzz_ltx fuzz_ltw fuzz_merl fuzz_tlp_archive fuzz_mmb fuzz_eos_model fuzz_npz_model
  fuzz_segbrain_kb fuzz_vtk_precheck
  fuzz_fluidsim fuzz_lmfsim_scene fuzz_capture fuzz_brdffit_json fuzz_quatpath_keys fuzz_patnet_inputs fuzz_tlp_pyramid
  fuzz_landmarks fuzz_transfer_function fuzz_dem_npy fuzz_hdrmerge_manifest fuzz_lmfsim_trajectory fuzz_scene_detect)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DFEST_FUZZ=ON -DFEST_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz --target "${targets[@]}"

seed_dirs() {  # the fixture folders whose files seed each target
  case "$1" in
    fuzz_mesh) echo tests/data/mesh tests/data/regress/mesh examples/data ;;
    fuzz_image_header) echo tests/data/image tests/data/regress/image ;;
    fuzz_volume) echo tests/data/volume tests/data/regress/volume ;;
    fuzz_json) echo tests/data/table tests/data/regress/json ;;
    fuzz_clers) echo tests/data/regress/clers ;;
    fuzz_ebm) echo tests/data/ebm tests/data/regress/ebm ;;
    fuzz_camera_json) echo tests/data/markerpose ;;
    fuzz_image_stream) echo tests/data/image ;;
    fuzz_patnet) echo examples/patnet tests/data/regress/patnet ;;
    fuzz_mgh) echo tests/data/volume ;;
    fuzz_vw) echo tests/data/volwave ;;
    fuzz_radiosity_scene) echo tests/data/radiosity examples/radiosity ;;
    fuzz_volume_source) echo tests/data/volume ;;
    fuzz_softobj) echo examples/tongue tests/data/regress/softobj ;;
    fuzz_lbm_case) echo examples/lbmsim ;;
    fuzz_ffd_lattice) echo tests/data/ffd ;;
    fuzz_v4l2_frame) echo tests/data/v4l2 ;;
    fuzz_feshape_xyz) echo tests/data/feshape ;;
    fuzz_ltx) echo tests/data/brdffit ;;
    fuzz_ltw) echo tests/data/brdffit ;;
    fuzz_merl) echo tests/data/brdffit ;;
    fuzz_tlp_archive) echo tests/data/terrainlod ;;
    fuzz_mmb) echo tests/data/facefit/seeds ;;
    fuzz_eos_model) echo tests/data/facefit/seeds ;;
    fuzz_npz_model) echo tests/data/facefit ;;
    fuzz_segbrain_kb) echo share/segbrain tests/data/regress/segbrain ;;
    fuzz_vtk_precheck) echo tests/data/dataset tests/data/vtk_bad tests/data/regress/dataset ;;
    fuzz_fluidsim) echo tests/data/fluidsim examples/fluidsim tests/data/regress/fluidsim ;;
    fuzz_lmfsim_scene) echo tests/data/lmfsim tests/data/regress/lmfsim ;;
    fuzz_capture) echo tests/data/capture examples/station tests/data/regress/capture ;;
    fuzz_hdrmerge_manifest) echo tests/data/capture ;;
    fuzz_lmfsim_trajectory) echo tests/data/lmfsim ;;
    fuzz_brdffit_json) echo tests/data/brdffit/json tests/data/regress/brdffit ;;
    fuzz_quatpath_keys) echo tests/data/quatpath examples/quatpath tests/data/regress/quatpath ;;
    fuzz_patnet_inputs) echo tests/data/patnet/inputs tests/data/regress/patnet_inputs ;;
    fuzz_tlp_pyramid) echo tests/data/terrainlod tests/data/regress/terrainlod ;;
    fuzz_landmarks) echo tests/data/facefit/landmarks tests/data/regress/landmarks ;;
    fuzz_transfer_function) echo tests/data/volrender/tf tests/data/regress/transfer_function ;;
    fuzz_dem_npy) echo tests/data/terrainlod/npy tests/data/regress/dem ;;
    fuzz_scene_detect) echo tests/data/mesh tests/data/scene_signatures ;;
  esac
}

mkdir -p build-fuzz/findings
run_one() {
  local t="$1" corpus="build-fuzz/corpus/$1"
  mkdir -p "$corpus"
  for d in $(seed_dirs "$t"); do
    # -size -1024k: find rounds sizes up to the unit, so -1M would match empty files only.
    [ -d "$d" ] && find "$d" -type f -size -1024k -exec cp -n {} "$corpus/" \; 2>/dev/null
  done
  echo "fuzz.sh: $t for ${seconds}s"
  # The fuzz build's UBSan checks are recoverable: halting on the first one makes an
  # undefined operation a finding with its input saved, not a line lost in the log.
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "build-fuzz/bin/$t" "$corpus" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -timeout=10 -artifact_prefix="build-fuzz/findings/$t-" -print_final_stats=1 \
    >"build-fuzz/$t.log" 2>&1 || echo "fuzz.sh: $t stopped with a finding (see build-fuzz/$t.log)"
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "build-fuzz/$t.log" | tail -2 | sed "s/^/$t: /"
}

# Two at a time: the reference machine has two cores.
pids=()
for t in "${targets[@]}"; do
  run_one "$t" &
  pids+=($!)
  if [ ${#pids[@]} -ge 2 ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
wait
ls build-fuzz/findings
