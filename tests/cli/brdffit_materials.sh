#!/usr/bin/env bash
# brdffit fit / cluster / project / normals end to end on inputs of known materials
# (tests/tools/brdffit_testdata): the answers come from the generating BRDFs, not from
# earlier runs. Then bad input: one clean line, the right status, nothing on stdout.
source "$(dirname "$0")/lib.sh"
gen="$FEST_BIN/brdffit_testdata"

near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

case_ "help"
run brdffit --help
expect_status 0
for s in fit cluster project normals; do check "help names $s" grep -q "$s" "$out"; done

case_ "fit: one lobe recovered from noiseless samples"
"$gen" samples onelobe 2000 3 0 > "$WORK/one.csv"
run brdffit fit "$WORK/one.csv" --threads 2
expect_status 0
expect_json '.lobes' 1
check "rho_d = 0.3" near "$(jq '.rho_d[1]' "$out")" 0.3 1e-5
check "Cxy = -1" near "$(jq '.Cxy[0][0]' "$out")" -1 1e-5
check "Cz = 1" near "$(jq '.Cz[0][2]' "$out")" 1 1e-5
check "N = 40" near "$(jq '.N[0][0]' "$out")" 40 1e-3

case_ "fit: 2 % noise within 5 %, from standard input, --robust and --shared-lobe run"
"$gen" samples onelobe 500 4 0.02 > "$WORK/noisy.csv"
run_stdin "$WORK/noisy.csv" brdffit fit --threads 2
expect_status 0
check "N within 5 %" near "$(jq '.N[0][1]' "$out")" 40 2
check "rho_d within 5 %" near "$(jq '.rho_d[0]' "$out")" 0.3 0.015
run brdffit fit "$WORK/noisy.csv" --robust huber:0.05 --shared-lobe --threads 2
expect_status 0
expect_json '.shared_lobe' true

case_ "fit --merl: a table in the MERL layout of the one-lobe BRDF"
"$gen" merl > "$WORK/one.binary"
run brdffit fit --merl "$WORK/one.binary" --fit-subsample 20000 --threads 2 --report "$WORK/fit.json"
expect_status 0
check "N = 40" near "$(jq '.N[0][0]' "$out")" 40 1e-3
check "report counts the measured cells" test "$(jq '.samples' "$WORK/fit.json")" -gt 1000000

case_ "cluster: three materials, 6 samples, 1 % noise"
"$gen" ltx 900 6 3 0.01 4 0 "$WORK/truth.csv" > "$WORK/s.ltx"
run_stdin "$WORK/s.ltx" brdffit cluster --clusters 3 --threads 2 --report "$WORK/cl.json"
expect_status 0
cp "$out" "$WORK/c.json"
expect_json '.clusters | length' 3
expect_json '[.clusters[].members] | sort' '[300,300,300]'
# The three albedos of tests/unit/brdffit_test_data.hpp, sorted by red: 0.05, 0.2, 0.7.
check "albedos of the materials" near "$(jq '[.clusters[].brdf.rho_d[0]] | sort | .[0]' "$WORK/c.json")" 0.05 0.005
check "albedos of the materials" near "$(jq '[.clusters[].brdf.rho_d[0]] | sort | .[1]' "$WORK/c.json")" 0.2 0.005
check "albedos of the materials" near "$(jq '[.clusters[].brdf.rho_d[0]] | sort | .[2]' "$WORK/c.json")" 0.7 0.01
expect_json '.history | length' 2

case_ "cluster --clusters auto stops at 3; same bytes with 1 and 2 threads"
run brdffit cluster --clusters auto "$WORK/s.ltx" --threads 1
expect_status 0
expect_json '.clusters | length' 3
run brdffit cluster --clusters 3 "$WORK/s.ltx" --threads 1
check "deterministic across thread counts" cmp -s "$out" "$WORK/c.json"

case_ "project: .ltw, projected error below the per-cluster error"
run brdffit project --clusters "$WORK/c.json" "$WORK/s.ltx" --threads 2 --report "$WORK/pr.json"
expect_status 0
cp "$out" "$WORK/w.ltw"
check "LUMIWGT1 magic" test "$(head -c 8 "$WORK/w.ltw")" = LUMIWGT1
check "projected < per-cluster" lt "$(jq '.error_projected' "$WORK/pr.json")" "$(jq '.error_per_cluster' "$WORK/pr.json")"
check "basis of 4" test "$(jq '.basis_size' "$WORK/pr.json")" -eq 4

case_ "normals: refined normals closer to the truth than the tilted mesh normals"
"$gen" ltx 200 8 1 0 5 8 "$WORK/truth2.csv" > "$WORK/b.ltx"
brdffit_bin="$FEST_BIN/brdffit"
"$brdffit_bin" cluster --clusters 1 "$WORK/b.ltx" > "$WORK/c2.json"
"$brdffit_bin" project --clusters "$WORK/c2.json" --basis 1 "$WORK/b.ltx" -o "$WORK/w2.ltw"
run brdffit normals --svbrdf "$WORK/w2.ltw" --ascii "$WORK/b.ltx" --report "$WORK/nr.json" --threads 2
expect_status 0
check "all refined" test "$(jq '.refined' "$WORK/nr.json")" -eq 200
check "residual decreased" lt "$(jq '.residual_after' "$WORK/nr.json")" "$(jq '.residual_before' "$WORK/nr.json")"
# Median angle to the truth (degrees) of the refined (columns 4-6) or mesh (7-9) normals.
median_angle() {
  awk -F'[ ,]' -v c="$3" 'NR == FNR { if (FNR > 1) { tx[FNR - 2] = $2; ty[FNR - 2] = $3; tz[FNR - 2] = $4 } next }
    body { i = n++; a = $c * tx[i] + $(c + 1) * ty[i] + $(c + 2) * tz[i]; if (a > 1) a = 1;
           print atan2(sqrt(1 - a * a), a) * 57.29578 }
    /^end_header/ { body = 1 }' "$1" "$2" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'
}
cp "$out" "$WORK/n1.ply"
refined=$(median_angle "$WORK/truth2.csv" "$WORK/n1.ply" 4)
mesh=$(median_angle "$WORK/truth2.csv" "$WORK/n1.ply" 7)
echo "median angle to the truth: refined $refined deg, mesh $mesh deg"
check "mesh normals 8 degrees off" near "$mesh" 8 0.01
# The cluster BRDF was itself fitted with the tilted normals, so it is biased (N 3 for
# 5): refined normals land within a quarter of the tilt, not at the truth.
check "refined median below 2.5 degrees" lt "$refined" 2.5
run brdffit normals --svbrdf "$WORK/w2.ltw" --ascii --alternate 2 "$WORK/b.ltx" --threads 2
expect_status 0
alt=$(median_angle "$WORK/truth2.csv" "$out" 4)
echo "with --alternate 2: $alt deg"
check "alternating with re-projection does not hurt" lt "$alt" "$refined"

case_ "bad input: wrong magic, truncated, too few samples, NaN, overflow, --clusters 0"
printf 'LUMITEXX\0\0\0\0' > "$WORK/bad.ltx"
run brdffit cluster "$WORK/bad.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has "LUMITEX1"
head -c 1000 "$WORK/s.ltx" > "$WORK/trunc.ltx"
run brdffit cluster "$WORK/trunc.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has "truncated"
"$gen" ltx 20 1 1 0 1 0 "$WORK/t3.csv" > "$WORK/one_sample.ltx"
run brdffit cluster "$WORK/one_sample.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has "no lumitexel has >= 2 samples"
head -c 100 "$WORK/w.ltw" > "$WORK/trunc.ltw"
run brdffit normals --svbrdf "$WORK/trunc.ltw" "$WORK/s.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has "trunc.ltw"
run brdffit normals --svbrdf "$WORK/w.ltw" "$WORK/b.ltx"
expect_clean_failure 3 brdffit
{ head -1 "$WORK/one.csv"; echo "0,0,1,0,0,1,nan,0.1,0.1"; } > "$WORK/nan.csv"
run brdffit fit "$WORK/nan.csv"
expect_clean_failure 3 brdffit
{ head -1 "$WORK/one.csv"; for i in 1 2 3 4 5; do echo "0.6,0,0.8,-0.6,0,0.8,1e300,1e300,1e300"; done; } > "$WORK/huge.csv"
run brdffit fit "$WORK/huge.csv"   # beyond the float range of the samples
expect_clean_failure 3 brdffit
expect_stderr_has "non-finite"
run brdffit cluster --clusters 0 "$WORK/s.ltx"
expect_clean_failure 2 brdffit
run brdffit fit --lobes 4 "$WORK/one.csv"
expect_clean_failure 2 brdffit
run brdffit project --clusters "$WORK/nope.json" "$WORK/s.ltx" -o "$WORK/x.ltw"
expect_clean_failure 4 brdffit
check "no partial output" test ! -e "$WORK/x.ltw"
: > "$WORK/empty"
run_stdin "$WORK/empty" brdffit cluster
expect_clean_failure 3 brdffit

finish
