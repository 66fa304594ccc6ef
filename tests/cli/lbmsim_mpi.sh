#!/usr/bin/env bash
# lbmsim over MPI (docs/lbmsim.md 6): 2, 3 and 4 ranks give the bytes of one process
# (fields and forces), more ranks than layers and a case on standard input are refused.
# Skipped (exit 77, with the reason) when lbmsim was built without MPI (-DFEST_MPI=OFF or
# no libopenmpi-dev) or mpirun is not installed.
. "$(dirname "$0")/lib.sh"
if ! "$FEST_BIN/lbmsim" --version | grep -q "with MPI"; then
  echo "skipped: this lbmsim was built without MPI (-DFEST_MPI=OFF, or libopenmpi-dev missing at configure time)" >&2
  exit 77
fi
if ! command -v mpirun >/dev/null; then
  echo "skipped: mpirun is not installed (Debian package openmpi-bin)" >&2
  exit 77
fi
mpi() { mpirun --oversubscribe --allow-run-as-root "$@" >"$out" 2>"$err"; rc=$?; }

cat >"$WORK/c3.json" <<'JSON'
{ "size": [20, 20, 20], "re": 100, "u_ref": 0.1, "collision": { "model": "trt" },
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0, 0] } }, "z-": "wall", "z+": "wall" },
  "geometry": [ { "sphere": { "center": [10, 7, 10], "radius": 3 } } ], "forces": [1],
  "steps": 100, "output": { "fields": ["velocity", "qcriterion"], "precision": "float64" } }
JSON
cat >"$WORK/cav.json" <<'JSON'
{ "size": [32, 32], "re": 100, "u_ref": 0.1,
  "faces": { "x-": "wall", "x+": "wall", "y-": "wall", "y+": { "moving": { "u": [0.1, 0] } } },
  "steps": 2000, "output": { "every": 1000, "fields": ["density", "velocity"], "precision": "float64" } }
JSON
# The sphere with interpolated (Bouzidi) walls: its links next to a cut read the
# neighbour rank's populations from the halo.
sed 's/"forces": \[1\],/"forces": [1], "curved_walls": "bouzidi",/' "$WORK/c3.json" >"$WORK/c3b.json"

for c in c3 c3b; do
  run lbmsim run "$WORK/$c.json" -o "$WORK/${c}_1.vti" --forces "$WORK/${c}_1.csv" --threads 1
  case_ "one process ($c)"
  expect_status 0
  case_ "MPI: 2 and 4 ranks give the bytes of one process (fields and forces, $c)"
  for np in 2 4; do
    mpi -np $np "$FEST_BIN/lbmsim" run "$WORK/$c.json" -o "$WORK/${c}_$np.vti" --forces "$WORK/${c}_$np.csv" --threads 1
    expect_status 0
    check "fields on $np ranks" cmp "$WORK/${c}_1.vti" "$WORK/${c}_$np.vti"
    check "forces on $np ranks" cmp "$WORK/${c}_1.csv" "$WORK/${c}_$np.csv"
  done
  case_ "MPI: 3 ranks split 20 layers unevenly, same bytes ($c)"
  mpi -np 3 "$FEST_BIN/lbmsim" run "$WORK/$c.json" -o "$WORK/${c}_3.vti" --threads 1
  expect_status 0
  check "fields on 3 ranks" cmp "$WORK/${c}_1.vti" "$WORK/${c}_3.vti"
done

case_ "MPI: more ranks than layers is refused"
mpi -np 4 "$FEST_BIN/lbmsim" run "$WORK/cav.json" --steps 1 --set 'size=[8,3]' -o "$WORK/x.vti"
check "non-zero status" test "$rc" -ne 0
expect_stderr_has 'lbmsim: error: 4 ranks for 3 layers along y'

case_ "MPI: a case on standard input is refused (rank 0 alone would read it)"
mpirun --oversubscribe --allow-run-as-root -np 2 "$FEST_BIN/lbmsim" run -o "$WORK/x.vti" <"$WORK/cav.json" >"$out" 2>"$err"
rc=$?
expect_status 2
expect_stderr_has 'lbmsim: error: mpirun gives standard input to rank 0 only'
finish
