; The eye-gaze automaton of two agents in dialog, seed 004 §23 (Pelachaud, with Becket's
; PaT-Nets).  The top level, as printed in the seed:
;
;   N0 (C1 or C2 or C3,  spawn(FA-feedback), N1)
;   N0 (C4 or C11,       spawn(FA-planning), N2)
;   N0 (C8 or C9 or C10, spawn(FA-comment),  N3)
;   N0 (C5 or C7,        spawn(FA-control),  N4)
;
; It reads a transcript row every cycle (--table dialog.tsv --table-var row, --dt 0.1) and
; prints the gaze actions A1-A6 of the sub-automata.  The seed names the conditions but
; not how they are read off the transcript; the readings below are ours (docs/patnet.md):
;
;   patnet run gaze.pat --table dialog.tsv --table-var row --dt 0.1 --until 60 --raw-print

(setf row nil)        ; the transcript row, bound by --table-var row from its first time on
(setf last-turn -1)
(setf turn-start 0.0)
(setf last-turn-length 10.0)
(setf question nil)   ; C9 and C10 are not in the transcript: set them with --events
(setf answer nil)

(defun col (name) (cdr (assoc name row)))
(defun floor1 () (< (col 'turn-state) 3))                 ; agent1 holds the floor
(defun speaker-gaze () (if (floor1) (col 'gaze1) (col 'gaze2)))
(defun listener-gaze () (if (floor1) (col 'gaze2) (col 'gaze1)))
(defun speaker () (if (floor1) "agent1" "agent2"))
(defun listener () (if (floor1) "agent2" "agent1"))
(defun silent-floor () (member (col 'turn-state) '(0 3)))
(defun say (a what) (format t "~a ~a ~a ~a~%" (/ (round (* 100 (motion-time))) 100.0) a (speaker) what))

(defnet gaze-top :locals '(p1 p2 p3 p5 p7 p8)
  ;; A condition holds at its onset only (true now, false when last tested), so a
  ;; state that lasts many rows starts one sub-automaton, not one per row.
  (defcond :c1 (let ((now (and (silent-floor) (= (listener-gaze) 1))) (was (val p1)))   ; grammatical pause
                 (val p1 now) (and now (not was))))
  (defcond :c2 (let ((now (and (silent-floor) (= 1 (if (floor1) (col 'adapt1) (col 'adapt2))))) (was (val p2)))
                 (val p2 now) (and now (not was))))                                   ; hesitation pause
  (defcond :c3 (let ((now (and (not (silent-floor)) (= 1 (if (floor1) (col 'smile1) (col 'smile2))))) (was (val p3)))
                 (val p3 now) (and now (not was))))                                   ; within-turn signal
  (defcond :c4 (when (/= (col 'turn) last-turn)                                     ; beginning of turn
                 (setf last-turn-length (- (motion-time) turn-start))
                 (setf turn-start (motion-time))
                 (setf last-turn (col 'turn))
                 t))
  (defcond :c5 (let ((now (and (silent-floor) (= (speaker-gaze) 1))) (was (val p5)))    ; end of turn
                 (val p5 now) (and now (not was))))
  (defcond :c7 (let ((now (member (col 'turn-state) '(2 5))) (was (val p7)))           ; turn-requesting signal
                 (val p7 now) (and now (not was))))
  (defcond :c8 (let ((now (= 1 (if (floor1) (col 'illus1) (col 'illus2)))) (was (val p8)))  ; accent
                 (val p8 now) (and now (not was))))
  (defcond :c9 question)
  (defcond :c10 answer)
  (defcond :c11 (and (< (- (motion-time) turn-start) 0.15) (< last-turn-length 2.0)))  ; short turn
  (defaction :feedback (send self :wait-fsm (send fa-feedback :new)))
  (defaction :planning (send self :wait-fsm (send fa-planning :new)))
  (defaction :comment (send self :wait-fsm (send fa-comment :new)))
  (defaction :control (send self :wait-fsm (send fa-control :new)))
  (defcond :have-row (not (null row)))
  (defnode start :no-op (:have-row n0))
  (defnode n0 :no-op (:c4 n2) (:c11 n2) (:c1 n1) (:c2 n1) (:c3 n1) (:c8 n3) (:c9 n3) (:c10 n3) (:c5 n4) (:c7 n4))
  (defnode n1 :feedback (:default n0))
  (defnode n2 :planning (:default n0))
  (defnode n3 :comment (:default n0))
  (defnode n4 :control (:default n0)))

; The sub-automata: each performs its gaze actions and exits.
(defnet fa-feedback   ; the speaker seeks feedback: A1 gaze toward the listener
  (defaction :a1 (say "A1" (format nil "gazes toward ~a" (listener))))
  (defnode f1 :a1 (:default exit)))
(defnet fa-planning   ; the speaker organises thoughts: A2 gaze away (looks less at turn start)
  (defaction :a2 (say "A2" (format nil "gazes away from ~a" (listener))))
  (defnode p1 :a2 (:default exit)))
(defnet fa-comment    ; accompanying speech: A3 gaze more; A6 when the listener looks back
  (defaction :a3 (say "A3" (format nil "gazes more at ~a" (listener))))
  (defaction :a6 (say "A6" "establishes mutual gaze"))
  (defcond :mutual (= (listener-gaze) 1))
  (defnode c1 :a3 (:mutual c2) (:default exit))
  (defnode c2 :a6 (:default exit)))
(defnet fa-control    ; channel control: mutual gaze at the end of an utterance (A6),
  (defaction :a6 (say "A6" "establishes mutual gaze"))   ; then A5 as the floor changes hands
  (defaction :a5 (say "A5" "breaks mutual gaze"))
  (defcond :holds (member (col 'turn-state) '(0 3)))
  (defnode k1 :a6 (:default hold))
  (defnode hold :no-op (:holds hold) (:default k2))
  (defnode k2 :a5 (:default exit)))

(setf top (send gaze-top :new))
