#!/usr/bin/env bash
# Unpack real test data (meshes, MRI heads, DEMs, HDR images, photos, a CFD mesh) from
# Debian packages into a cache folder outside the source tree. Installs nothing:
# `apt-get download` + `dpkg-deb --fsys-tarfile`.
#
#   scripts/fetch-test-data.sh [DIR]    DIR defaults to $FEST_TESTDATA, else
#                                       ${XDG_CACHE_HOME:-~/.cache}/fest/testdata
#
# About 200 MB of .deb files are downloaded into a temporary folder and about 24 MB kept.
# Nothing is done when DIR/MANIFEST already lists the same package versions. Tests that
# need the data skip with a message when DIR/MANIFEST is missing.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '2,11p' "$0"; exit 0 ;; esac
test_data_dir="${1:-${FEST_TESTDATA:-${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}}"

SUDO=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then SUDO="sudo"; fi
apt_updated=0
apt_update_once() {
  if [ "$apt_updated" -eq 0 ]; then
    $SUDO apt-get update -qq
    apt_updated=1
  fi
}


# package  path-inside-package  destination (relative to DIR)
DATA_FILES=$(cat <<'EOF'
insighttoolkit5-examples usr/share/doc/insighttoolkit5-examples/examples/Data/KmeansTest_T1UCharRaw.nii.gz mri/t1_head.nii.gz
insighttoolkit5-examples usr/share/doc/insighttoolkit5-examples/examples/Data/KmeansTest_T1KmeansPrelimSegmentation.nii.gz mri/t1_kmeans_labels.nii.gz
insighttoolkit5-examples usr/share/doc/insighttoolkit5-examples/examples/Data/KmeansTest_T1RawSkullStrip.nii.gz mri/t1_skullstrip_labels.nii.gz
insighttoolkit5-examples usr/share/doc/insighttoolkit5-examples/examples/Data/BrainT1Slice.png mri/brain_t1_slice.png
insighttoolkit5-examples usr/share/doc/insighttoolkit5-examples/examples/Data/BrainProtonDensitySlice.png mri/brain_pd_slice.png
python-matplotlib-data usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz dem/jacksboro_fault_dem.npz
python-matplotlib-data usr/share/matplotlib/mpl-data/sample_data/topobathy.npz dem/topobathy.npz
python-matplotlib-data usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg faces/grace_hopper.jpg
r-cran-stars usr/lib/R/site-library/stars/tif/olinda_dem_utm25s.tif dem/olinda_dem_utm25s.tif
r-cran-terra usr/lib/R/site-library/terra/ex/elev.tif dem/luxembourg_elev.tif
r-cran-terra usr/lib/R/site-library/terra/ex/meuse.tif dem/meuse.tif
blender-data usr/share/blender/datafiles/studiolights/world/city.exr hdr/city.exr
blender-data usr/share/blender/datafiles/studiolights/world/courtyard.exr hdr/courtyard.exr
blender-data usr/share/blender/datafiles/studiolights/world/forest.exr hdr/forest.exr
blender-data usr/share/blender/datafiles/studiolights/world/interior.exr hdr/interior.exr
blender-data usr/share/blender/datafiles/studiolights/world/night.exr hdr/night.exr
blender-data usr/share/blender/datafiles/studiolights/world/studio.exr hdr/studio.exr
blender-data usr/share/blender/datafiles/studiolights/world/sunrise.exr hdr/sunrise.exr
blender-data usr/share/blender/datafiles/studiolights/world/sunset.exr hdr/sunset.exr
blender-data usr/share/blender/datafiles/studiolights/matcap/metal_shiny.exr hdr/matcap_metal_shiny.exr
blender-data usr/share/blender/datafiles/studiolights/matcap/clay_studio.exr hdr/matcap_clay_studio.exr
python3-skimage usr/lib/python3/dist-packages/skimage/data/astronaut.png faces/astronaut.png
python3-skimage usr/lib/python3/dist-packages/skimage/data/camera.png images/camera.png
opencv-data usr/share/opencv4/haarcascades/haarcascade_frontalface_default.xml faces/haarcascade_frontalface_default.xml
opencv-data usr/share/opencv4/lbpcascades/lbpcascade_frontalface_improved.xml faces/lbpcascade_frontalface_improved.xml
opencv-doc usr/share/doc/opencv-doc/examples/viz/data/bunny.ply meshes/bunny_scan.ply
opencv-doc usr/share/doc/opencv-doc/examples/data/messi5.jpg faces/messi5.jpg
mricron-data usr/share/mricron/templates/ch2.nii.gz mri/ch2.nii.gz
mricron-data usr/share/mricron/templates/ch2bet.nii.gz mri/ch2bet.nii.gz
mricron-data usr/share/mricron/templates/aal.nii.gz mri/aal.nii.gz
mricron-data usr/share/mricron/templates/aal.nii.txt mri/aal.nii.txt
mricron-data usr/share/mricron/templates/jhu189.nii.gz mri/jhu189.nii.gz
mricron-data usr/share/mricron/templates/ch2better.nii.gz mri/ch2better.nii.gz
opencv-doc usr/share/doc/opencv-doc/examples/data/aloeL.jpg images/aloeL.jpg
opencv-doc usr/share/doc/opencv-doc/examples/data/aloeR.jpg images/aloeR.jpg
dolfin-doc usr/share/dolfin/demo/undocumented/advection-diffusion/dolfin_fine.xml.gz cfd/dolfin_fine_mesh.xml.gz
dolfin-doc usr/share/dolfin/demo/undocumented/advection-diffusion/dolfin_fine_velocity.xml.gz cfd/dolfin_fine_velocity.xml.gz
dolfin-doc usr/share/dolfin/demo/documented/bcs/aneurysm.xml.gz cfd/aneurysm_mesh.xml.gz
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/functional.nii volumes/nibabel/functional.nii
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/example4d.nii.gz volumes/nibabel/example4d.nii.gz
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/example_nifti2.nii.gz volumes/nibabel/example_nifti2.nii.gz
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/anatomical.nii volumes/nibabel/anatomical.nii
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/reoriented_anat_moved.nii volumes/nibabel/reoriented_anat_moved.nii
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/standard.nii.gz volumes/nibabel/standard.nii.gz
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/test.mgz volumes/nibabel/test.mgz
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/analyze.hdr volumes/nibabel/analyze.hdr
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/nifti1.hdr volumes/nibabel/nifti1.hdr
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/nifti2.hdr volumes/nibabel/nifti2.hdr
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/row_major.dconn.nii volumes/nibabel/row_major.dconn.nii
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/minc1_4d.mnc volumes/nibabel/minc1_4d.mnc
python3-nibabel usr/lib/python3/dist-packages/nibabel/tests/data/minc2_4d.mnc volumes/nibabel/minc2_4d.mnc
assimp-testmodels usr/share/assimp/models/OBJ/WusonOBJ.obj meshes/assimp/WusonOBJ.obj
assimp-testmodels usr/share/assimp/models/OBJ/spider.obj meshes/assimp/spider.obj
assimp-testmodels usr/share/assimp/models/OBJ/box_longline.obj meshes/assimp/box_longline.obj
assimp-testmodels usr/share/assimp/models/OBJ/regr_3429812.obj meshes/assimp/regr_3429812.obj
assimp-testmodels usr/share/assimp/models/OBJ/space_in_material_name.obj meshes/assimp/space_in_material_name.obj
assimp-testmodels usr/share/assimp/models/OBJ/concave_polygon.obj meshes/assimp/concave_polygon.obj
assimp-testmodels usr/share/assimp/models/OBJ/testline.obj meshes/assimp/testline.obj
assimp-testmodels usr/share/assimp/models/OBJ/testpoints.obj meshes/assimp/testpoints.obj
assimp-testmodels usr/share/assimp/models/OBJ/testmixed.obj meshes/assimp/testmixed.obj
assimp-testmodels usr/share/assimp/models/PLY/Wuson.ply meshes/assimp/Wuson.ply
assimp-testmodels usr/share/assimp/models/3DS/test1.3ds meshes/assimp/test1.3ds
assimp-testmodels usr/share/assimp/models/Collada/duck.dae meshes/assimp/duck.dae
assimp-testmodels usr/share/assimp/models/FBX/box.fbx meshes/assimp/box.fbx
assimp-testmodels usr/share/assimp/models/X/test.x meshes/assimp/test.x
assimp-testmodels usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb meshes/assimp/BoxTextured.glb
assimp-testmodels usr/share/assimp/models/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf meshes/assimp/BoxTextured.gltf
invesalius-examples usr/share/doc/invesalius-examples/examples/Cranium.inv3 volumes/Cranium.inv3
EOF
)
CGAL_MESHES="bunny00.off armadillo.off ChineseDragon-10kv.off elephant.off elephant-with-holes.off fandisk.off cow.off eight.off femur.off mushroom.off lion.off camel.off bull.off homer.off man.off mannequin-devil.off knot1.off turbine.off head.off hand.off bones.off ellipsoid.off icosahedron.off octahedron.off cube.off blobby.off"
CALIB_IMAGES="left01 left02 left03 left04 left05 left06 left07 left08 left09 left11 left12 left13 left14"
DATA_PKGS="$(echo "$DATA_FILES" | awk '{print $1}' | sort -u | tr '\n' ' ')libcgal-demo"

mkdir -p "$test_data_dir"
test_data_dir="$(cd "$test_data_dir" && pwd)"
data_manifest() {  # "<package> <candidate version>" per line, sorted
  # shellcheck disable=SC2086
  apt-cache policy $DATA_PKGS 2>/dev/null |
    awk '/^[^ ].*:$/{sub(":$","");p=$0} /Candidate:/{print p, $2}' | sort
}
# The Khronos glTF validator (npm registry), for tests/interop/gltf.sh: pinned, best
# effort (the test skips with a message without it), kept under DIR/npm.
GLTF_VALIDATOR=gltf-validator@2.0.0-dev.3.10
if command -v npm >/dev/null 2>&1; then
  if ! grep -qs '"version": "2.0.0-dev.3.10"' "$test_data_dir/npm/node_modules/gltf-validator/package.json"; then
    mkdir -p "$test_data_dir/npm"
    npm install --prefix "$test_data_dir/npm" --no-audit --no-fund --silent "$GLTF_VALIDATOR" >/dev/null 2>&1 ||
      echo "fetch-test-data.sh: warning: npm could not install $GLTF_VALIDATOR; tests/interop/gltf.sh will skip" >&2
  fi
else
  echo "fetch-test-data.sh: note: npm not installed; tests/interop/gltf.sh will skip"
fi

manifest_new="$(data_manifest)"
# A listed file missing from the cache (a path added to DATA_FILES for a package already
# fetched, e.g. mri/ch2better.nii.gz) is fetched again; Cranium.inv3 is unpacked and removed.
all_files_present() {
  while read -r _ _ dest; do
    [ -n "$dest" ] && [ "$dest" != volumes/Cranium.inv3 ] && [ ! -f "$test_data_dir/$dest" ] && return 1
  done <<< "$DATA_FILES"
  return 0
}
if [ -f "$test_data_dir/MANIFEST" ] && [ "$(cat "$test_data_dir/MANIFEST")" = "$manifest_new" ] && all_files_present; then
  echo "fetch-test-data.sh: test data in $test_data_dir is up to date"
  exit 0
fi
apt_update_once
manifest_new="$(data_manifest)"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
chown _apt "$work" 2>/dev/null || true   # lets apt download without its sandbox warning
echo "fetch-test-data.sh: downloading test data packages: $DATA_PKGS"
# shellcheck disable=SC2086  # word splitting of the package list is intended
(cd "$work" && apt-get download -qq $DATA_PKGS)

# one pass over each package: unpack only the wanted paths, then copy them into place
for n in $CALIB_IMAGES; do
  DATA_FILES+=$'\n'"opencv-doc usr/share/doc/opencv-doc/examples/data/$n.jpg calib/$n.jpg"
done
DATA_FILES+=$'\n'"libcgal-demo usr/share/doc/libcgal-dev/data.tar.gz cgal-data.tar.gz"
for pkg in $DATA_PKGS; do
  mapfile -t paths < <(echo "$DATA_FILES" | awk -v p="$pkg" '$1==p{print "./"$2}')
  mkdir -p "$work/x/$pkg"
  dpkg-deb --fsys-tarfile "$(ls "$work/${pkg}"_*.deb)" | tar -x -C "$work/x/$pkg" "${paths[@]}"
done
while read -r pkg path dest; do
  [ -n "$pkg" ] || continue
  mkdir -p "$test_data_dir/$(dirname "$dest")"
  cp "$work/x/$pkg/$path" "$test_data_dir/$dest"
done <<< "$DATA_FILES"
# CGAL's demo data is a tarball inside the package
mkdir -p "$test_data_dir/meshes"
for m in $CGAL_MESHES; do
  tar -xzf "$test_data_dir/cgal-data.tar.gz" -O "data/meshes/$m" > "$test_data_dir/meshes/$m"
done
mkdir -p "$test_data_dir/points" "$test_data_dir/volumes"
for p in kitten.xyz sphere_1k.xyz; do
  tar -xzf "$test_data_dir/cgal-data.tar.gz" -O "data/points_3/$p" > "$test_data_dir/points/$p"
done
tar -xzf "$test_data_dir/cgal-data.tar.gz" -O data/images/liver.inr.gz > "$test_data_dir/volumes/liver.inr.gz"
rm -f "$test_data_dir/cgal-data.tar.gz"
# InVesalius' Cranium CT (isosurf, volrender): a gzip tar whose matrix.dat is raw int16
# little-endian, x fastest, 256 x 256 x 108, spacing from its main.plist; kept as NRRD.
{
  printf 'NRRD0004\n# Cranium.inv3 (invesalius-examples): ProMED CT 0051\ntype: int16\ndimension: 3\n'
  printf 'sizes: 256 256 108\nspacings: 0.9570312 0.9570312 1.5\nencoding: raw\nendian: little\n\n'
  tar -xzf "$test_data_dir/volumes/Cranium.inv3" --wildcards -O '*/matrix.dat'
} > "$test_data_dir/volumes/cranium.nrrd"
rm -f "$test_data_dir/volumes/Cranium.inv3"

echo "$manifest_new" > "$test_data_dir/MANIFEST"
echo "fetch-test-data.sh: test data ready in $test_data_dir ($(du -sh "$test_data_dir" | cut -f1))"
