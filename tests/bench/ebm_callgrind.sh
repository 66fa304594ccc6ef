#!/bin/bash
# Instruction counts (valgrind --tool=callgrind, deterministic where wall-clock time on a
# shared machine is not) of one call of each coder per bench_ebm_vs_draco row: ebcode's
# encode_ebm / decode_ebm (without the re-encoding check, and with it: the calls inside
# the bench's profile_decode and profile_verified_decode) against Draco cl7's
# Encoder::EncodeMeshToBuffer / Decoder::DecodeMeshFromBuffer, measured in the same process.
# One JSON line per mesh and qp.
#
#   [EBM_ROWS="camel 11,bunny00 14"] tests/bench/ebm_callgrind.sh [BENCH_BINARY] [TESTDATA_DIR]
#       (defaults: build/bin/bench_ebm_vs_draco, $FEST_TESTDATA or ~/.cache/fest/testdata)
set -u
bench=${1:-build/bin/bench_ebm_vs_draco}
data=${2:-${FEST_TESTDATA:-$HOME/.cache/fest/testdata}}
command -v valgrind >/dev/null || { echo '{"bench":"ebm_callgrind","skipped":"valgrind not installed"}'; exit 0; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rows=("fandisk 11" "fandisk 14" "camel 11" "camel 14" "ChineseDragon-10kv 11" "ChineseDragon-10kv 14" \
      "armadillo 11" "armadillo 14" "bunny00 11" "bunny00 14" "bunny_sub2 14")
[ -n "${EBM_ROWS:-}" ] && IFS=, read -r -a rows <<< "$EBM_ROWS"   # e.g. EBM_ROWS="camel 11,bunny00 14"
for row in "${rows[@]}"; do
  set -- $row
  line=$(valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$bench" "$data" --profile "$1" "$2" 2>/dev/null) || {
    echo "{\"bench\":\"ebm_callgrind\",\"mesh\":\"$1\",\"skipped\":\"profile run failed\"}"; continue; }
  t=$(echo "$line" | sed 's/.*"triangles":\([0-9]*\).*/\1/')
  ann=$(callgrind_annotate --inclusive=yes "$out/cg" 2>/dev/null)
  ir() { echo "$ann" | grep -F "$1" | head -1 | awk '{gsub(",","",$1); print $1}'; }
  ee=$(ir "fest::edgebreaker::encode_ebm[abi:cxx11](fest::TriangleSoup const&, fest::edgebreaker::EncodeOptions const&, fest::edgebreaker::EncodeStats*) [")
  ed=$(ir "profile_decode(")
  ev=$(ir "profile_verified_decode(")
  de=$(ir "draco::Encoder::EncodeMeshToBuffer(")
  dd=$(ir "draco::Decoder::DecodeMeshFromBuffer(")
  echo "{\"bench\":\"ebm_callgrind\",\"mesh\":\"$1\",\"qp\":$2,\"triangles\":$t,\"ebm_encode_ir\":$ee,\"ebm_decode_ir\":$ed,\"ebm_decode_verified_ir\":$ev,\"draco_cl7_encode_ir\":$de,\"draco_cl7_decode_ir\":$dd,\"ebm_encode_ir_per_tri\":$((ee / t)),\"ebm_decode_ir_per_tri\":$((ed / t)),\"ebm_decode_verified_ir_per_tri\":$((ev / t)),\"draco_cl7_encode_ir_per_tri\":$((de / t)),\"draco_cl7_decode_ir_per_tri\":$((dd / t))}"
done
