;; A synthetic two-agent dialog transcript in the layout of seed 004 §23: every 0.1 s
;; a row of the time and twenty parameters (turn number, turn state 0-5, vocalisation,
;; gaze at the other's face, adaptors, illustrators, body-focus movements, back-channels,
;; head nods, posture, smiles; each for agent1 and agent2).  No real transcripts of this
;; kind are public; this generator is a PaT-Net itself, with the generating
;; probabilities written below, so the transcript is reproducible (--seed) and its
;; statistics are known:
;;
;;   patnet run dialog_gen.pat --dt 0.1 --cycles 600 --seed 3 --raw-print > dialog.tsv
;;
;; Turn states (seed): 0-2 agent1 has the floor (0 nobody speaks, 1 agent1 speaks, 2 both),
;; 3-5 agent2 has it (3 nobody, 4 agent2 speaks, 5 both).  Gaze follows the seed's rules
;; of thumb: the listener looks more than the speaker, the speaker looks more when
;; pausing than when talking.

(setf tab "	")
(setf turn 0)
(defun bit (percent) (if (< (random 100) percent) 1 0))
(defun row (ts)
  (let* ((a1 (< ts 3))                          ; agent1 holds the floor
         (v1 (if (or (= ts 1) (= ts 2) (= ts 5)) 1 0))
         (v2 (if (or (= ts 4) (= ts 5) (= ts 2)) 1 0))
         (speaking (if a1 (= v1 1) (= v2 1)))
         (g-speaker (bit (if speaking 40 70)))
         (g-listener (bit 75))
         (g1 (if a1 g-speaker g-listener))
         (g2 (if a1 g-listener g-speaker)))
    (format t "~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~a~%"
            (/ (round (* 10 (motion-time))) 10.0) tab turn tab ts tab v1 tab v2 tab g1 tab g2 tab
            (bit 5) tab (bit 5) tab (bit (* 30 v1)) tab (bit (* 30 v2)) tab (bit 3) tab (bit 3) tab
            (bit (if a1 0 10)) tab (bit (if a1 10 0)) tab (bit (if a1 0 8)) tab (bit (if a1 8 0)) tab
            (random 3) tab (random 3) tab (bit 10) tab (bit 15))))

(defnet dialog-gen
  (defaction :header
    (format t "t~aturn~aturn_state~avoc1~avoc2~agaze1~agaze2~aadapt1~aadapt2~aillus1~aillus2~afocus1~afocus2~abc1~abc2~anod1~anod2~aposture1~aposture2~asmile1~asmile2~%"
            tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab tab))
  (defaction :r0 (row 0)) (defaction :r1 (row 1)) (defaction :r2 (row 2))
  (defaction :r3 (row 3)) (defaction :r4 (row 4)) (defaction :r5 (row 5))
  (defaction :give12 (setf turn (+ turn 1)) (row 4))   ; agent2 takes the floor speaking
  (defaction :give21 (setf turn (+ turn 1)) (row 1))
  ;; agent1's floor: mostly speaking, short pauses, rare overlaps, then the floor passes
  (defnode start :header (:default ts1))
  (def-probnode ts0 :r0 (0.55 ts0) (0.35 ts1) (0.10 pass12))
  (def-probnode ts1 :r1 (0.90 ts1) (0.05 ts0) (0.03 ts2) (0.02 pass12))
  (def-probnode ts2 :r2 (0.50 ts2) (0.30 ts1) (0.20 pass12))
  (def-probnode ts3 :r3 (0.55 ts3) (0.35 ts4) (0.10 pass21))
  (def-probnode ts4 :r4 (0.90 ts4) (0.05 ts3) (0.03 ts5) (0.02 pass21))
  (def-probnode ts5 :r5 (0.50 ts5) (0.30 ts4) (0.20 pass21))
  (defnode pass12 :give12 (:default ts4))
  (defnode pass21 :give21 (:default ts1)))

(send dialog-gen :new)
