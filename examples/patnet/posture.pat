; The posture transition network of seed 004 §8: six static postures and the Transit
; algorithm over a transition matrix M.  M(x,y) is -1 (no transition), a motion sequence
; (a lower-case string: execute it), or a posture z (go x -> z, then z -> y).  The seed's
; matrix (its Fig. 4) is not legible; this one is illustrative (docs/patnet.md).
;
;   patnet run posture.pat --eval "(send posture-net :new 'stand 'prone)" --raw-print

(setf postures '(stand squat supine sit prone kneel))   ; 0..5 as in the seed

(setf m '(( nil           "squat-down"     3            "sit-down"        5             "kneel-down")
          ( "stand-up"    nil              3            "squat-to-sit"    5             "squat-to-kneel")
          ( -1            3                nil          "sit-up"          "roll-over"   4)
          ( "stand-from-sit" "sit-to-squat" "lie-back"  nil               2             1)
          ( 5             5                "roll-back"  2                 nil           "push-up-to-kneel")
          ( "rise"        "kneel-to-squat" 3            1                 "lower-to-prone" nil)))

(defun index-of (p l i) (cond ((null l) -1) ((eq p (car l)) i) (t (index-of p (cdr l) (+ i 1)))))
(defun posture-index (p) (index-of p postures 0))

; Transit(x, y, M): the list of motion sequences from posture x to posture y, or
; IMPOSSIBLE.  Depth guards against a matrix whose intermediate postures loop.
(defun transit (x y depth)
  (let ((e (nth y (nth x m))))
    (cond ((= x y) nil)
          ((> depth 8) 'impossible)
          ((null e) nil)
          ((and (numberp e) (= e -1)) 'impossible)
          ((numberp e)
           (let ((a (transit x e (+ depth 1))) (b (transit e y (+ depth 1))))
             (if (or (eq a 'impossible) (eq b 'impossible)) 'impossible (append a b))))
          (t (list e)))))

(defnet posture-net :locals '(from to plan)
  (definit (from to) (val from from) (val to to))
  (defaction :plan
    (val plan (transit (posture-index (val from)) (posture-index (val to)) 0)))
  (defcond :impossible (eq (val plan) 'impossible))
  (defcond :more (not (null (val plan))))
  ; one motion sequence per second of motion time
  (defaction :play
    (format t "~a -> ~a: ~a~%" (val from) (val to) (car (val plan)))
    (val plan (cdr (val plan)))
    (send self :wait-time (+ (motion-time) 1.0)))
  (defaction :arrive (format t "~a -> ~a: reached ~a~%" (val from) (val to) (val to)))
  (defaction :refuse
    (format t "~a -> ~a: no transition~%" (val from) (val to))
    (send self :exit 'failed))
  (defnode plan :plan (:impossible refuse) (:more play) (:default arrive))
  (defnode play :play (:more play) (:default arrive))
  (defnode arrive :arrive (:default exit))
  (defnode refuse :refuse (:default exit)))
