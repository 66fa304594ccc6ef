; Two semaphores taken together and released in the next node (seed 004, appendix A
; section 3C5), with two instances x and y competing for them.
(setf s1 (send semaphore :new))
(setf s2 (send semaphore :new))

(defnet semwait1
  (defaction :action1
    (format t "in state 1~%")
    (send self :wait-semaphore s1)
    (send self :wait-semaphore s2))
  (defaction :action2
    (format t "in state 2~%")
    (send self :signal-semaphore s1)
    (send self :signal-semaphore s2))
  (defnode state1 :action1 (:default state2))
  (defnode state2 :action2 (:default exit)))

(setf x (send semwait1 :new))
(setf y (send semwait1 :new))
