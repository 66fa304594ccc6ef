#!/usr/bin/env bash
# capture run's journal with two encoder threads (docs/capture.md §3):
# faults while several shots are being encoded and written, then --resume. The journal
# must list shots strictly in plan order, each once, each only once its file is complete
# (sha256sum, an independent program, checks the files against it), and the resumed
# session must hold the same bytes as an uninterrupted one.
source "$(dirname "$0")/lib.sh"
D="$FEST_FIXTURES/capture"
cp "$D/small_scene.json" "$D/small_station.json" "$D/small_plan.json" "$WORK/"
S="$WORK/small_station.json" P="$WORK/small_plan.json"
cd "$WORK"
# Sessions are named by their folders: compare all but the name and the timestamps.
norm='del(.session) | del(.started) | del(.shots[].time)'

# journal_files SESSION: the shot files of the journal, in journal order.
journal_files() { jq -r 'select(.shot) | .shot.file' "$1/manifest.journal"; }
# plan_files: the files of the plan, in plan order (the dry run lists them).
"$FEST_BIN/capture" run --station "$S" --plan "$P" -o never --dry-run | jq -r '.files[]' > plan_files
# same_files A B: every shot file of the plan byte-identical in both sessions.
same_files() { while read -r f; do cmp -s "$1/$f" "$2/$f" || { echo "differs: $f" >&2; return 1; }; done < plan_files; }
# journal_is_prefix SESSION: the journal's shots are the plan's first N, in order, once each.
journal_is_prefix() {
  journal_files "$1" > "$1.journaled"
  head -n "$(wc -l < "$1.journaled")" plan_files | cmp -s - "$1.journaled"
}
# journal_hashes_ok SESSION: every journaled file hashes to its journaled SHA-256.
journal_hashes_ok() {
  jq -r 'select(.shot) | "\(.shot.sha256)  \(.shot.file)"' "$1/manifest.journal" > "$1.sums"
  (cd "$1" && sha256sum --quiet -c "../$1.sums")
}

case_ "reference: an uninterrupted session"
run capture run --station "$S" --plan "$P" -o ref
expect_status 0
cp "$out" ref.json
check "reference journal in plan order" journal_is_prefix ref
check "reference journal holds every shot" test "$(journal_files ref | wc -l)" -eq "$(wc -l < plan_files)"

case_ "a write failing mid-view while later shots are encoded: nothing after it is journaled"
# A folder squats the name of a001/L0/e05.png (the 20th shot: a silhouette and 12
# exposures per view), so renaming its file into place fails (exit 4) while the other
# encoder is already on the next shot.
k=$(grep -n '^a001/L0/e05.png$' plan_files | cut -d: -f1)
check "a001/L0/e05.png is the 20th shot of the plan" test "$k" -eq 20
mkdir -p blocked/a001/L0/e05.png
run capture run --station "$S" --plan "$P" -o blocked
expect_clean_failure 4 capture
expect_stderr_has 'a001/L0/e05.png'
check "aborted manifest" test "$(jq -r .status blocked/manifest.json)" = aborted
check "journal in plan order, each shot once" journal_is_prefix blocked
check "journal stops right before the failed shot (19 shots)" test "$(journal_files blocked | wc -l)" -eq 19
check "journaled files hash as recorded" journal_hashes_ok blocked
check "no temporary files left" test -z "$(find blocked -name '*.tmp.*')"
check "the manifest lists the 19 journaled shots" test "$(jq '.shots | length' blocked/manifest.json)" -eq 19
rmdir blocked/a001/L0/e05.png
run capture run --station "$S" --plan "$P" -o blocked --resume
expect_status 0
check "resumed manifest equals the reference but for timestamps" cmp <(jq -S "$norm" "$out") <(jq -S "$norm" ref.json)
check "journal: every plan shot once" bash -c "jq -r 'select(.shot) | .shot.file' blocked/manifest.journal | sort | uniq -d | grep -q . && exit 1; test \$(jq -r 'select(.shot) | .shot.file' blocked/manifest.journal | wc -l) -eq $(wc -l < plan_files)"
check "the same bytes as the reference" same_files ref blocked

case_ "SIGKILL with encodes in flight, then --resume"
# A longer plan (8 views) killed once some 30 shots are journaled: whatever the encoders
# had in hand is lost with the process, and the journal must still be a clean prefix.
jq '.angles_deg = {"count": 8}' "$P" > long_plan.json
"$FEST_BIN/capture" run --station "$S" --plan long_plan.json -o ref8 > ref8.json 2> /dev/null
"$FEST_BIN/capture" run --station "$S" --plan long_plan.json -o killed > /dev/null 2> "$err" &
pid=$!
for _ in $(seq 300); do
  n=$(grep -c '"shot"' killed/manifest.journal 2> /dev/null)
  [ "${n:-0}" -ge 30 ] && break
  sleep 0.02
done
kill -KILL "$pid"; wait "$pid"; rc=$?
check "killed by the signal (status $rc)" test "$rc" -eq 137
"$FEST_BIN/capture" run --station "$S" --plan long_plan.json -o never8 --dry-run | jq -r '.files[]' > plan_files
n=$(journal_files killed | wc -l)
check "killed mid-session ($n of $(wc -l < plan_files) shots journaled)" test "$n" -ge 30 -a "$n" -lt "$(wc -l < plan_files)"
check "journal in plan order, each shot once" journal_is_prefix killed
check "journaled files hash as recorded" journal_hashes_ok killed
run capture run --station "$S" --plan long_plan.json -o killed --resume
expect_status 0
check "resumed manifest equals the uninterrupted one but for timestamps" cmp <(jq -S "$norm" "$out") <(jq -S "$norm" ref8.json)
check "no shot journaled twice" test -z "$(journal_files killed | sort | uniq -d)"
check "every plan shot journaled" test "$(journal_files killed | wc -l)" -eq "$(wc -l < plan_files)"
check "the same bytes as the uninterrupted session" same_files ref8 killed

finish
