#!/bin/bash
# patnet: the seed's worked example (App. A §1) against the cycle lists derived by hand
# in docs/patnet.md, the semaphore example (App. A §3C5), probabilistic arcs, check, dot,
# markov, and bad input.
. "$(dirname "$0")/lib.sh"
EX="$(cd "$(dirname "$0")/../../examples/patnet" && pwd)"
GOLD="$FEST_FIXTURES/patnet"

case_ "worked example: enter cycles per node (hand-derived, docs/patnet.md)"
run patnet run "$EX/samp.pat" --dump-locals
expect_status 0
got=$(jq -r 'select(.ev=="enter") | "\(.var) \(.node) \(.cycle)"' "$out" |
      awk '{k=$1" "$2; a[k]=a[k] s[k] $3; s[k]=","} END{for(k in a) print k, a[k]}' | sort | tr '\n' ';')
want="fred STATE1 1,3,5,7,9;fred STATE2 2,4,6,8,10;fred STATE3 11,13,15;fred STATE4 12,14,16;sam STATE1 1,3,5;sam STATE2 2,4,6;sam STATE3 7,9;sam STATE4 8,10;"
if [ "$got" = "$want" ]; then pass; else fail "enter cycles: $got"; fi
got=$(jq -c 'select(.ev=="exit") | [.var,.cycle,.locals.A,.locals.B]' "$out" | tr '\n' ' ')
if [ "$got" = '["sam",10,"6","5"] ["fred",16,"6","5"] ' ]; then pass; else fail "exits: $got"; fi
# Within a cycle fred's events precede sam's.
got=$(jq -r 'select(.cycle==3) | .var' "$out" | uniq | tr '\n' ' ')
if [ "$got" = "fred sam " ]; then pass; else fail "interleaving: $got"; fi

case_ "worked example: golden trace (byte-exact)"
if cmp -s "$out" "$GOLD/samp.jsonl"; then pass; else fail "trace differs from tests/data/patnet/samp.jsonl"; fi

case_ "--eval creates instances; TSV trace has the same events"
run patnet run "$EX/samp.pat" --eval "(send samp-fsm :new 5 4)" --trace tsv
expect_status 0
if head -1 "$out" | grep -q $'^cycle\tt\tnet\tevent\tdetail$'; then pass; else fail "TSV header"; fi
if grep -q $'^4\t0.133333\tsamp-fsm#3\texit\tfinished$' "$out"; then pass; else fail "third instance (a=5, b=4) should exit at cycle 4"; fi

case_ "semaphores: print events at cycles 1 x, 1 y, 2 x, 3 y (App. A §3C5)"
run patnet run "$EX/semaphore.pat"
expect_status 0
got=$(jq -r 'select(.ev=="print") | "\(.cycle) \(.var) \(.text)"' "$out" | tr '\n' ';')
if [ "$got" = "1 x in state 1;1 y in state 1;2 x in state 2;3 y in state 2;" ]; then pass; else fail "prints: $got"; fi
if cmp -s "$out" "$GOLD/semaphore.jsonl"; then pass; else fail "trace differs from tests/data/patnet/semaphore.jsonl"; fi
run patnet run "$EX/semaphore.pat" --raw-print
if [ "$(cat "$out" | tr '\n' ';')" = "in state 1;in state 1;in state 2;in state 2;" ]; then pass; else fail "--raw-print: $(head -c 200 "$out")"; fi

case_ "spawn and waits (App. A §3B, §3C): resumes at cycles 5, 9, 100 (hand-derived)"
run patnet run "$EX/spawn.pat"
expect_status 0
got=$(jq -r 'select(.net=="spawner#1" and (.ev=="resume" or .ev=="exit")) | "\(.ev)@\(.cycle)"' "$out" | tr '\n' ' ')
if [ "$got" = "resume@5 resume@9 resume@100 exit@100 " ]; then pass; else fail "spawner: $got"; fi
if cmp -s "$out" "$GOLD/spawn.jsonl"; then pass; else fail "trace differs from tests/data/patnet/spawn.jsonl"; fi

case_ "--realtime paces cycles with the wall clock"
start=$(date +%s%N)
run patnet run "$EX/semaphore.pat" --realtime --dt 0.2 --raw-print
elapsed=$(( ($(date +%s%N) - start) / 1000000 ))
if [ "$rc" -eq 0 ] && [ "$elapsed" -ge 550 ]; then pass; else fail "3 cycles of 0.2 s took $elapsed ms (rc $rc)"; fi

case_ "wait-time (+ (motion-time) 3.0) at 30 fps: 90 cycles"
printf '%s\n' "(defnet sl (defaction :z (send self :wait-time (+ (motion-time) 3.0))) (defnode a :z (:default exit)))" \
  "(send sl :new)" > "$WORK/sleep.pat"
run patnet run "$WORK/sleep.pat"
expect_json 'select(.ev=="resume") | .cycle' 91

case_ "probabilistic node 10/70/20 %: 10,000 draws within 99.9 % binomial intervals; fixed by --seed"
printf '%s\n' "(defnet pn (def-probnode state1 :no-op (0.1 state1) (0.7 state2) (0.2 state3))" \
  "(defnode state2 :no-op (:default state1)) (defnode state3 :no-op (:default state1)))" \
  "(dotimes (i 100) (send pn :new))" > "$WORK/prob.pat"
run patnet run "$WORK/prob.pat" --cycles 200 --seed 42 --trace tsv
cp "$out" "$WORK/a.tsv"
counts=$(awk -F'\t' '$4=="arc" && $5 ~ /^STATE1 0\./ {split($5,f," "); n[f[3]]++; t++} END{print t, n["STATE1"]+0, n["STATE2"]+0, n["STATE3"]+0}' "$WORK/a.tsv")
if awk -v c="$counts" 'BEGIN{split(c,x," "); t=x[1]; if (t<9000) exit 1; split("0.1 0.7 0.2",p," ");
     for(i=1;i<=3;i++){f=x[i+1]/t; s=sqrt(p[i]*(1-p[i])/t); if (f<p[i]-3.29*s || f>p[i]+3.29*s) exit 1} }'; then pass
else fail "frequencies out of interval: draws, STATE1, STATE2, STATE3 = $counts"; fi
run patnet run "$WORK/prob.pat" --cycles 200 --seed 42 --trace tsv
if cmp -s "$out" "$WORK/a.tsv"; then pass; else fail "same seed, different trace"; fi
run patnet run "$WORK/prob.pat" --cycles 200 --seed 43 --trace tsv
if ! cmp -s "$out" "$WORK/a.tsv"; then pass; else fail "another seed gave the same trace"; fi

case_ "check: a clean net passes; a broken one lists errors with file:line:col"
run patnet check "$EX/samp.pat"
expect_status 0
printf '%s\n' "(defnet bad" "  (defcond c1 t)" "  (defnode s1 :go (:nocond s2) (:default s9)))" > "$WORK/bad.pat"
run patnet check "$WORK/bad.pat"
expect_status 3
expect_stderr_has "patnet: error: condition name C1 must start with ':' \(.*bad.pat:2:12\)"
expect_stderr_has "undefined action :GO \(.*bad.pat:3:15\)"
expect_stderr_has "undefined condition :NOCOND \(.*bad.pat:3:19\)"
expect_stderr_has "arc to undefined node S9 \(.*bad.pat:3:32\)"

case_ "dot: valid Graphviz"
run patnet dot "$EX/samp.pat"
expect_status 0
if command -v dot >/dev/null; then check "dot parses the output" dot -Tsvg -o "$WORK/n.svg" "$out"; fi
if grep -q '"samp-fsm/STATE2" -> "samp-fsm/STATE1" \[label=":C1"\]' "$out"; then pass; else fail "edge STATE2 -:C1-> STATE1"; fi

case_ "bad input: unknown node, runaway code, malformed files, events"
printf '%s\n' "(defnet x (defnode a :no-op (:default zz)))" "(send x :new)" > "$WORK/unknown.pat"
run patnet run "$WORK/unknown.pat"
expect_clean_failure 3 patnet
expect_stderr_has "undefined node ZZ \(.*unknown.pat:1:29\)"
printf '%s\n' "(defnet x (defnode a :no-op (:default a))" > "$WORK/open.pat"
run patnet run "$WORK/open.pat"
expect_clean_failure 3 patnet
expect_stderr_has "unbalanced '\('.*open.pat:1:1"
printf '%s\n' "(defnet x (defaction :spin (dotimes (i 100000000) i)) (defnode a :spin (:default exit)))" "(send x :new)" > "$WORK/spin.pat"
run patnet run "$WORK/spin.pat" --max-steps 100000
expect_status 1
expect_stderr_has "more than 100000 evaluation steps"
if [ "$(tail -1 "$out" | jq -r .ev)" = "error" ]; then pass; else fail "trace should end with an error event"; fi
printf '%s\n' "(defun f (n) (f n))" "(defnet x (defaction :go (f 1)) (defnode a :go (:default exit)))" "(send x :new)" > "$WORK/rec.pat"
run patnet run "$WORK/rec.pat"
expect_status 1
expect_stderr_has "nested deeper"
: > "$WORK/empty.pat"
run patnet run "$WORK/empty.pat"
expect_status 0
expect_stdout_empty
run patnet run "$WORK/missing.pat"
expect_clean_failure 4 patnet
printf '%s\n' '{"t": 1.0, "set": {"a": 1}}' '{"t": 0.5, "set": {"a": 2}}' > "$WORK/ev.jsonl"
run patnet run "$EX/samp.pat" --events "$WORK/ev.jsonl"
expect_clean_failure 3 patnet
expect_stderr_has "must not decrease.*ev.jsonl:2"
printf '%s\n' '{"t": "soon"}' > "$WORK/ev2.jsonl"
run patnet run "$EX/samp.pat" --events "$WORK/ev2.jsonl"
expect_clean_failure 3 patnet
run patnet run "$EX/samp.pat" --cycles -3
expect_status 2

case_ "a loop that never yields: warned by check, stopped by --max-cycles (exit 1)"
printf '%s\n' "(defnet spin (defnode a :no-op (:default b)) (defnode b :no-op (:default a)))" "(send spin :new)" > "$WORK/spin.pat"
run patnet check "$WORK/spin.pat"
expect_status 0
expect_stderr_has "warning: the loop A -> B -> A never ends: .*spin.pat:1:23"
run patnet run "$WORK/spin.pat" --max-cycles 500
expect_status 1
expect_stderr_has "cycle limit \(500 cycles\)"
if [ "$(tail -1 "$out" | jq -r .ev)" = "error" ]; then pass; else fail "trace should end with an error event"; fi

case_ "events drive a net: spawn and set"
printf '%s\n' "(defnet greeter (definit (who) (format t \"hello ~a~%\" who)) (defnode a :no-op (:default exit)))" > "$WORK/greet.pat"
printf '%s\n' '{"t": 0.1, "spawn": ["greeter", "agent1"]}' '{"t": 0.2, "eval": "(send greeter :new (quote agent2))"}' > "$WORK/ev3.jsonl"
run patnet run "$WORK/greet.pat" --events "$WORK/ev3.jsonl" --raw-print
if [ "$(tr '\n' ';' < "$out")" = "hello agent1;hello AGENT2;" ]; then pass; else fail "spawned: $(cat "$out")"; fi

case_ "posture network (§8): every pair but the matrix's -1 reaches its goal"
run patnet run "$EX/posture.pat" --raw-print \
  --eval "(dolist (a postures) (dolist (b postures) (unless (eq a b) (send posture-net :new a b))))"
expect_status 0
if [ "$(grep -c ': reached ' "$out")" -eq 29 ]; then pass; else fail "$(grep -c ': reached ' "$out") of 29 pairs reached"; fi
if [ "$(grep 'no transition' "$out")" = "SUPINE -> STAND: no transition" ]; then pass; else fail "the -1 pair: $(grep 'no transition' "$out")"; fi

case_ "markov round trip: a known 24-state chain, sampled, estimated within 4 sigma per entry"
# P(i -> i) = 0.6, P(i -> i+1) = 0.3, P(i -> i+7) = 0.1 (mod 24), as a net of def-probnodes
{ echo "(defnet chain :start S0"
  for i in $(seq 0 23); do echo "  (def-probnode S$i :no-op (0.6 S$i) (0.3 S$(( (i + 1) % 24 ))) (0.1 S$(( (i + 7) % 24 ))))"; done
  echo ")"; echo "(send chain :new)"; } > "$WORK/chain.pat"
run patnet run "$WORK/chain.pat" --cycles 100000 --seed 5 --trace tsv
awk -F'\t' 'BEGIN{print "state"} $4=="enter"{print substr($5,2)}' "$out" > "$WORK/states.csv"
run patnet markov "$WORK/states.csv" --cols state --states 24
expect_status 0
if awk -F, 'NR>1 { i=$1; for (j=0;j<24;j++) { p=0; if (j==i) p=0.6; else if (j==(i+1)%24) p=0.3; else if (j==(i+7)%24) p=0.1;
       sd = sqrt((p>0 ? p*(1-p) : 0.0001) / 4166); d=$(j+2)-p; if (d<0) d=-d; if (d > 4*sd) { print i, j, $(j+2), p; bad=1 } } }
       END { exit bad }' "$out"; then pass; else fail "estimate outside 4 sigma"; fi
run patnet markov "$WORK/states.csv" --cols state --states 24 --net chain2
expect_status 0
check "the estimated net passes check" bash -c "'$FEST_BIN/patnet' check '$out'"
run patnet markov "$EX/dialog.tsv" --net gaze24
expect_status 0
expect_stderr_has "warning: .* states have no observed transition"
printf 't\tturn_state\tgaze1\tgaze2\n0\t7\t0\t0\n0.1\t1\t0\t1\n' > "$WORK/badts.tsv"
run patnet markov "$WORK/badts.tsv"
expect_clean_failure 3 patnet

finish
