#!/usr/bin/env bash
# lbmsim check all-fast: Poiseuille's error law and TRT's exactness, Taylor-Green at second
# order, the Ghia cavity, the Schaefer-Turek cylinder, mass, mirror symmetry, determinism.
. "$(dirname "$0")/lib.sh"
case_ "check all-fast passes every criterion"
run lbmsim check all-fast
expect_status 0
expect_json '.pass' 'true'
expect_json '[.cases[].case]' '["poiseuille","taylor-green","cavity","cylinder20","mass","symmetry","determinism"]'
expect_json '.cases[] | select(.case=="cavity") | .metrics.max_dev_u_vertical_line <= 0.007' 'true'
# Schaefer & Turek (1996) 2D-1, published intervals: C_D in [5.57, 5.59], C_L in [0.0104, 0.0110].
expect_json '.cases[] | select(.case=="cylinder20") | .metrics | (.cd >= 5.57 and .cd <= 5.59 and .cl >= 0.0104 and .cl <= 0.0110)' 'true'
finish
