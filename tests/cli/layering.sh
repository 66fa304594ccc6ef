#!/usr/bin/env bash
# Layering: dependencies point one way (README.md, "Layout"). This test reads the source
# tree only -- every `#include "..."` line and the CMake lists -- and needs no build:
#
#   lib-include      lib/<domain>/ includes only its own domain, lib/core and the shared
#                    domains: lib/reflectance (BRDFs, cameras, rasteriser) and
#                    lib/volume_pyramid (multi-resolution volumes, used by volwave,
#                    volrender and isosurf alike; the project treats it as a second shared
#                    domain). Never formats/, devices/ or tools/.
#   formats-include  formats/ includes only formats/ and lib/core.
#   tool-include     tools/<tool>/ includes lib/, formats/, devices/ and its own folder,
#                    never another tool's folder.
#   devices-include  devices/ never includes tools/ (nothing includes tools/).
#   test-compiles-tool  no CMake list under tests/ names a tool's .cpp as a source, and no
#                    test source #includes one: tests link fest_<tool>_app instead.
#   flag-in-lib      no string literal in lib/ names a command-line flag ("--name"): lib/
#                    reports errors in the domain's terms and the tool translates them.
#                    lib/cli is exempt: it is the argument-parsing library of the tools.
#   tool-main / tool-app  every tools/<tool>/ has a main.cpp, and when it has other .cpp
#                    files its CMakeLists.txt builds them as the library fest_<tool>_app.
#
# Include names resolve the way the compiler finds them: first against the including
# file's folder, then against the include roots the CMake lists set (the repository root,
# lib/, a tool's own folder); an include that resolves nowhere in the tree is a system or
# third-party header and is not judged, unless it names formats/, tools/ or devices/.
#
# LAYERING_TRACE=1 prints how every include line resolved.
#
# KNOWN_VIOLATIONS lists what is knowingly wrong, one line per violation ("file: rule:
# what"); it is empty since issue 20 was finished and should stay so. A violation not listed
# fails, and a listed one that has gone fails too, so that the list only ever shrinks.
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export FEST_BIN="${FEST_BIN:-$source_dir}"  # lib.sh wants it; this test runs no executable
source "$source_dir/lib.sh"
ROOT="$(cd "$source_dir/../.." && pwd)"
export LC_ALL=C  # one collation for sort and comm

# "--name" inside a string literal in lib/ that is not a command-line flag (text of a
# domain's own format that happens to use "--"): "file: --name". None so far.
FLAG_EXCEPTIONS=(
)

KNOWN_VIOLATIONS=(
)

found="$WORK/found"
: >"$found"
violation() { printf '%s: %s: %s\n' "$1" "$2" "$3" >>"$found"; }

# area PATH: sets $AREA to the layer a repository-relative path belongs to (lib/<domain>,
# formats, tools/<tool>, devices, tests, or other). Functions set variables rather than
# print, so that the loop over ~2500 include lines forks nothing.
area() {
  case "$1" in
    lib/*/*) AREA="${1#lib/}"; AREA="lib/${AREA%%/*}" ;;
    formats/*) AREA=formats ;;
    tools/*/*) AREA="${1#tools/}"; AREA="tools/${AREA%%/*}" ;;
    devices/*) AREA=devices ;;
    tests/*) AREA=tests ;;
    *) AREA=other ;;
  esac
}

# normalise PATH: sets $NORM to PATH without "./" and "dir/.." components.
normalise() {
  local IFS=/ part out=()
  for part in $1; do
    case "$part" in
      ''|.) ;;
      ..) [ ${#out[@]} -gt 0 ] && unset 'out[${#out[@]}-1]' ;;
      *) out+=("$part") ;;
    esac
  done
  NORM="${out[*]}"
}

# resolve FILE INCLUDE: sets $TARGET to the repository-relative path the include names,
# or to "" when it is not in the tree (system and third-party headers).
resolve() {
  local file="$1" inc="$2" dir="${1%/*}" r cand
  local roots=("$dir" "" lib)
  case "$file" in
    tools/*/*) r="${file#tools/}"; roots+=("tools/${r%%/*}") ;;
    tests/*) roots+=(tests/unit) ;;
  esac
  for r in "${roots[@]}"; do
    cand="${r:+$r/}$inc"
    if [ -f "$cand" ]; then
      case "$cand" in *./*) normalise "$cand"; TARGET="$NORM" ;; *) TARGET="$cand" ;; esac
      return
    fi
  done
  # A test may reach a tool's folder through fest_<tool>_app's include directory.
  if [ "${file%%/*}" = tests ]; then
    for cand in tools/*/"$inc"; do [ -f "$cand" ] && { TARGET="$cand"; return; }; done
  fi
  case "$inc" in
    formats/*|tools/*|devices/*|lib/*) TARGET="$inc" ;;
    ../*) normalise "$dir/$inc"; TARGET="$NORM" ;;
    *) TARGET="" ;;
  esac
}

# --- includes ----------------------------------------------------------------------------
cd "$ROOT" || exit 1
includes=0
while IFS= read -r line; do
  file="${line%%:*}"
  rest="${line#*:}"
  inc="${rest#*\"}"; inc="${inc%%\"*}"
  includes=$((includes + 1))
  resolve "$file" "$inc"
  target="$TARGET"
  [ -z "${LAYERING_TRACE:-}" ] || echo "trace: $file: \"$inc\" -> ${target:-(not in the tree)}"
  [ -n "$target" ] || continue
  area "$file"; from="$AREA"
  area "$target"; to="$AREA"
  case "$from" in
    lib/*)
      case "$to" in
        "$from"|lib/core|lib/reflectance|lib/volume_pyramid) ;;
        *) violation "$file" lib-include "$target" ;;
      esac ;;
    formats)
      case "$to" in
        formats|lib/core) ;;
        *) violation "$file" formats-include "$target" ;;
      esac ;;
    tools/*)
      case "$to" in
        "$from"|lib/*|formats|devices) ;;
        *) violation "$file" tool-include "$target" ;;
      esac ;;
    devices)
      case "$to" in tools/*) violation "$file" devices-include "$target" ;; esac ;;
    tests)
      case "$target" in tools/*.cpp|tools/*.cc) violation "$file" test-compiles-tool "$target" ;; esac ;;
  esac
done < <(grep -rHE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"[^"]+"' \
           --include='*.cpp' --include='*.hpp' --include='*.h' --include='*.cc' --include='*.inl' \
           lib formats tools devices tests 2>/dev/null)
case_ "the include lines were read"
if [ "$includes" -gt 100 ]; then pass; else fail "only $includes include lines found under $ROOT"; fi

# --- tests and benchmarks do not compile tool sources ------------------------------------
# Every C++ source a CMake list under tests/ names (comments dropped), resolved the way
# CMake does (against ${PROJECT_SOURCE_DIR}, else against the list's own folder): none may
# lie under tools/. Include directories are not sources and are not judged.
while IFS= read -r cm; do
  cmdir="${cm%/*}"
  while IFS= read -r src; do
    case "$src" in
      '${PROJECT_SOURCE_DIR}/'*|'${CMAKE_SOURCE_DIR}/'*) path="${src#*\}/}" ;;
      '${CMAKE_CURRENT_SOURCE_DIR}/'*|'${CMAKE_CURRENT_LIST_DIR}/'*) path="$cmdir/${src#*\}/}" ;;
      '$'*) continue ;;  # another variable: not resolvable here
      *) path="$cmdir/$src" ;;
    esac
    normalise "$path"
    case "$NORM" in tools/*) violation "$cm" test-compiles-tool "$NORM" ;; esac
  done < <(sed 's/#.*//' "$cm" | grep -oE '[^[:space:]()"]+\.(cpp|cc|cxx|c)\b')
done < <(find tests -name CMakeLists.txt | sort)

# --- no flag names in lib/ string literals -----------------------------------------------
# A small scanner that knows comments, string and character literals (and skips raw
# strings), so that a flag named in a comment is not counted.
LITERALS_AWK='
    FNR == 1 { state = "code" }
    {
      line = $0; n = length(line); i = 1
      if (state == "line") state = "code"
      while (i <= n) {
        c = substr(line, i, 1); c2 = substr(line, i, 2)
        if (state == "block") { if (c2 == "*/") { state = "code"; i += 2 } else i++; continue }
        if (state == "code") {
          if (c2 == "//") { state = "line"; break }
          if (c2 == "/*") { state = "block"; i += 2; continue }
          if (c2 == "R\"") {  # raw string: skip to )delim"
            p = index(substr(line, i + 2), "("); delim = substr(line, i + 2, p - 1)
            e = index(substr(line, i), ")" delim "\"")
            if (e > 0) { i += e + length(delim) + 1; continue }
            break
          }
          if (c == "\x27" && i > 1 && substr(line, i - 1, 1) ~ /[0-9A-Fa-f]/) { i++; continue }  # digit separator
          if (c == "\x27") {  # character literal
            i++; while (i <= n && substr(line, i, 1) != "\x27") { if (substr(line, i, 1) == "\\") i++; i++ }
            i++; continue
          }
          if (c == "\"") { lit = ""; i++
            while (i <= n && substr(line, i, 1) != "\"") {
              if (substr(line, i, 1) == "\\") { lit = lit substr(line, i, 2); i += 2; continue }
              lit = lit substr(line, i, 1); i++
            }
            i++
            # Each "--name" in the literal that is not inside a word: a flag.
            while (match(lit, /(^|[^-A-Za-z0-9])--[A-Za-z][A-Za-z0-9-]*/)) {
              flag = substr(lit, RSTART, RLENGTH); if (substr(flag, 1, 1) != "-") flag = substr(flag, 2)
              print FILENAME "\t" flag; lit = substr(lit, RSTART + RLENGTH)
            }
            continue
          }
          i++; continue
        }
      }
    }'
while IFS=$'\t' read -r file flag; do
  skip=0
  for ex in "${FLAG_EXCEPTIONS[@]}"; do [ "$ex" = "$file: $flag" ] && skip=1; done
  [ "$skip" -eq 0 ] || continue
  violation "$file" flag-in-lib "$flag"
done < <(find lib -path lib/cli -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z |
           xargs -0 awk "$LITERALS_AWK")

# --- every tool: main.cpp, and the other .cpp files as fest_<tool>_app -------------------
for dir in tools/*/; do
  tool=$(basename "$dir")
  [ -f "$dir/main.cpp" ] || violation "${dir%/}" tool-main "no main.cpp"
  others=$(find "$dir" -name '*.cpp' ! -path "${dir}main.cpp" | head -1)
  if [ -n "$others" ] && ! sed 's/#.*//' "$dir/CMakeLists.txt" 2>/dev/null | grep -Eq "(fest_library|add_library)\([[:space:]]*fest_${tool}_app([[:space:]]|\)|\$)"; then
    violation "${dir%/}" tool-app "no fest_${tool}_app library for its other .cpp files"
  fi
done

# --- compare with KNOWN_VIOLATIONS -------------------------------------------------------
sort -u "$found" -o "$found"
known="$WORK/known"
printf '%s\n' "${KNOWN_VIOLATIONS[@]}" | sed '/^[[:space:]]*$/d' | sort -u >"$known"
while IFS= read -r v; do
  case_ "new layering violation"
  fail "$v"
done < <(comm -23 "$found" "$known")
while IFS= read -r v; do
  case_ "fixed: remove it from KNOWN_VIOLATIONS in tests/cli/layering.sh"
  fail "$v"
done < <(comm -13 "$found" "$known")
case_ "no new violation, none fixed but still listed"
if comm -3 "$found" "$known" | grep -q .; then fail "see above"; else pass; fi
echo "$(wc -l <"$found") violations found; KNOWN_VIOLATIONS lists $(wc -l <"$known")"
finish
