; Spawning and waiting (seed 004, appendix A sections 3B and 3C): a net creates a child
; and waits for it to exit, then waits for a second child to pass through node A2, then
; waits three seconds of motion time.  With patnet's cycle rules (docs/patnet.md) the
; spawner resumes at cycles 5, 9 and 100 and exits at 100.
(defnet another-fsm :locals '(n)
  (definit (n) (val n n))
  (defnode a1 :no-op (:default a2))
  (defnode a2 :no-op (:default a3))
  (defnode a3 :no-op (:default exit)))

(defnet spawner :locals '(waiting-for)
  (defaction :action1
    (val waiting-for (send another-fsm :new 56))
    (send self :wait-fsm (val waiting-for)))
  (defaction :watch (send self :wait-fsm (send another-fsm :new 7) :state 'a2))
  (defaction :sleep (send self :wait-time (+ (motion-time) 3.0)))
  (defnode state1 :action1 (:default state2))
  (defnode state2 :watch (:default state3))
  (defnode state3 :sleep (:default exit)))

(setf p (send spawner :new))
