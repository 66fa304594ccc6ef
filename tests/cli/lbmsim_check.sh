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
finish
