# Helpers for tests/interop/*.sh: every file fest writes, read back by a program that
# does not share fest's code. Sourced after tests/cli/lib.sh.
#
#   reader assimp assimp-utils || true   # 0 when the command exists; else records a skip
#   PY=/usr/bin/python3                  # Debian's Python: where python3-vtk9/-nibabel live
#   py_has vtk                           # the module imports in $PY
#   finish_interop                       # like finish, but exit 77 when nothing ran

PY=/usr/bin/python3
skipped_readers=()

# reader COMMAND PACKAGE: is an independent reader installed? Says what is skipped if not.
reader() {
  if command -v "$1" >/dev/null 2>&1; then return 0; fi
  echo "interop: skip: $1 not installed (Debian package $2)"
  skipped_readers+=("$1")
  return 1
}

# py_has MODULE PACKAGE: can Debian's Python import MODULE?
py_has() {
  if [ -x "$PY" ] && "$PY" -c "import $1" >/dev/null 2>&1; then return 0; fi
  echo "interop: skip: Python module $1 not installed (Debian package $2)"
  skipped_readers+=("python:$1")
  return 1
}

finish_interop() {
  if [ $((passed + failed)) -eq 0 ]; then
    echo "interop: no independent reader installed (${skipped_readers[*]}): skipped"
    exit 77
  fi
  [ ${#skipped_readers[@]} -gt 0 ] && echo "interop: readers not installed: ${skipped_readers[*]}"
  finish
}
