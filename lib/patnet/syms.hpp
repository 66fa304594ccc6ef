#pragma once
// Symbols and built-in function ids the compiler and evaluator compare against
// (internal to lib/patnet).

#include "patnet/machine.hpp"

namespace fest::patnet {

enum Builtin : int {
  B_ADD, B_SUB, B_MUL, B_DIV, B_INC, B_DEC, B_NUMEQ, B_NUMNE, B_LT, B_GT, B_LE, B_GE, B_MIN, B_MAX, B_ABS,
  B_SQRT, B_EXPT, B_EXP, B_LOG, B_SIN, B_COS, B_TAN, B_ATAN, B_FLOOR, B_ROUND, B_MOD, B_RANDOM, B_NOT, B_NULL,
  B_EQ, B_EQL, B_EQUAL, B_LIST, B_CONS, B_CAR, B_CDR, B_CADR, B_NTH, B_LENGTH, B_APPEND, B_REVERSE, B_MEMBER,
  B_ASSOC, B_FUNCALL, B_APPLY, B_FORMAT, B_PRINT, B_PRINC, B_MOTION_TIME, B_MOTION_FIND, B_NUMBERP, B_COUNT
};
extern const char* const builtin_names[B_COUNT];

struct Machine::Syms {
  int quote, function, lambda, if_, cond, when, unless, and_, or_, progn, let, letstar, setq, setf, defun, dolist,
      dotimes, return_, val, var, send, self, t, nil, defnet, definit, defaction, defcond, defnode, def_probnode,
      def_weightnode, def_randnode, defmonitor, list, exit, k_noop, k_default, k_locals, k_classvars, k_parents,
      k_start, k_new, k_exit, k_status, k_add_dependent, k_wait_fsm, k_wait_time, k_wait_condition, k_wait_motion,
      k_wait_semaphore, k_signal_semaphore, k_state, k_priority, finished, failed, idle, running, waiting,
      semaphore, amp_optional, amp_key, amp_rest;
  int builtin_sym[B_COUNT];
};

}  // namespace fest::patnet
