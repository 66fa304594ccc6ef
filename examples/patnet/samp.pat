; The worked example of the PaT-Nets documentation (seed 004, appendix A section 1):
; two counters, a up to 6 and b up to 5, interleaved through four nodes.
(defnet samp-fsm :locals '(a b)
  (definit (a b) (val a a) (val b b))
  (defaction :inca (val a (1+ (val a))))
  (defaction :incb (val b (1+ (val b))))
  (defcond :c1 (< (val a) 6))
  (defcond :c2 (< (val b) 5))
  (defnode state1 :inca (:default state2))
  (defnode state2 :no-op (:c1 state1) (:default state3))
  (defnode state3 :incb (:default state4))
  (defnode state4 :no-op (:c2 state3) (:default exit)))

(setf fred (send samp-fsm :new 1 2))
(setf sam  (send samp-fsm :new 3 3))
