#!/usr/bin/env bash
# --progress on real data (scripts/fetch-test-data.sh; skipped when not fetched): the bar
# reaches 100 %, nothing is drawn without it (standard error is a file here), and standard
# output and the files written are the same bytes either way -- as progress_everywhere.sh,
# on inputs of the size the bars are for.
source "$(dirname "$0")/lib.sh"
source "$(dirname "$0")/progress_pair.sh"
cranium=$(need_testdata volumes/cranium.nrrd) || exit 77
olinda=$(need_testdata dem/olinda_dem_utm25s.tif) || exit 77

# A CT head of 14 MB: the extraction by slabs (about a second) and the wavelet coder's phases.
pair isosurf_cranium isosurf exact "$cranium" --iso 500 -o skull.ply --threads 2
pair volwave_cranium volwave encode "$cranium" --max-error 1 -o c.vw --threads 2
pair volwave_cranium_decode volwave decode "$WORK/volwave_cranium.plain/c.vw" -o c.nrrd --threads 2

# The Olinda DEM: its pyramid built, checked against the DEM with cameras, one view extracted.
pair terrainlod_olinda_build terrainlod build "$olinda" -o o.tlp --threads 2
pair terrainlod_olinda_verify terrainlod verify "$WORK/terrainlod_olinda_build.plain/o.tlp" --dem "$olinda" --cameras 4
pair terrainlod_olinda_extract terrainlod extract "$WORK/terrainlod_olinda_build.plain/o.tlp" -o v.ply --png v.png

finish
