#!/usr/bin/env bash
# Install the Debian 12 (bookworm) packages that the project builds and tests with.
#
#   scripts/install-deps.sh                 toolchain + libraries + hardware-free test tools
#   scripts/install-deps.sh --no-test-tools toolchain + libraries only
#
# Idempotent: when everything is already installed it runs no apt-get at all and
# returns in well under a second; a fresh install takes about a minute and about
# 1.2 GB of disk (libvtk9-dev alone pulls about 250 packages).
# Real test data is fetched separately by scripts/fetch-test-data.sh.
set -euo pipefail

# --- what the project needs -------------------------------------------------
BUILD_PKGS=(
  g++ cmake ninja-build pkg-config
  libcli11-dev          # CLI11 2.1.2  find_package(CLI11)   -> CLI11::CLI11
  libfmt-dev            # fmt 9.1.0    find_package(fmt)     -> fmt::fmt
  libeigen3-dev         # Eigen 3.4.0  find_package(Eigen3)  -> Eigen3::Eigen
  libopenmesh-dev       # OpenMesh 9.0 find_package(OpenMesh) -> OpenMeshCore OpenMeshTools
  libdraco-dev          # Draco 1.5.5  find_package(draco)   -> draco::draco
  libassimp-dev         # assimp 5.2.5 find_package(assimp)  -> assimp::assimp (glTF/DAE/FBX/3DS input, plugin module)
  libopencv-dev         # OpenCV 4.6.0 find_package(OpenCV)  -> opencv_core ...
  libopenexr-dev        # OpenEXR 3.1.5 find_package(OpenEXR) -> OpenEXR::OpenEXR
  libvtk9-dev           # VTK 9.1.0    find_package(VTK)     -> VTK::<Module>
  libgpiod-dev          # libgpiod 1.6.3 (v1 API)  pkg-config libgpiod / libgpiodcxx
  libusb-1.0-0-dev      # libusb 1.0.26            pkg-config libusb-1.0
  libgtest-dev libgmock-dev  # GoogleTest 1.12.1 find_package(GTest) -> GTest::gtest ...
  nlohmann-json3-dev    # JSON 3.11.2  find_package(nlohmann_json) -> nlohmann_json::nlohmann_json
  libgdal-dev           # GDAL 3.6.2   find_package(GDAL)    -> GDAL::GDAL (DEMs, GeoTIFF)
  libfftw3-dev          # FFTW 3.3.10  pkg-config fftw3 / fftw3f
  zlib1g-dev            # .nii.gz, .nrrd gzip encoding
  libpng-dev libjpeg62-turbo-dev libtiff-dev   # formats/image codecs, used directly (not via OpenCV imgcodecs: start-up, issue 21)
  libminizip-dev        # minizip 1.1  pkg-config minizip (facefit: .npz model import)
  libssl-dev            # OpenSSL 3.0  find_package(OpenSSL) -> OpenSSL::Crypto (brdffit: SHA-256 of meshes in .ltx)
  ccache                # faster rebuilds on 2 cores
  clang libclang-rt-14-dev   # libFuzzer and sanitizer runtimes for the fuzz targets
  make                  # examples/Makefile and Makefile.inc
  libode-dev            # ODE 0.16.2  pkg-config ode (lmfsim benchmark anchor only)
  libssl-dev            # OpenSSL 3.0 find_package(OpenSSL) -> OpenSSL::Crypto (SHA-256 of capture files)
  libnifti2-dev         # nifti_clib 3.0.1  find_package(NIFTI) -> NIFTI::niftiio (NIfTI-1/-2, Analyze headers)
  linux-libc-dev        # linux/videodev2.h: capture's V4L2 cameras, driven directly (not via OpenCV videoio: start-up, issue 21)
)
TEST_TOOL_PKGS=(
  umockdev libumockdev-dev   # USB (usbdevfs) and GPIO emulation without hardware
  xvfb xauth                 # X server for VTK rendering tests (Debian's VTK is X11-only)
  jq                         # CLI tests read the JSON that tools print
  unzip                      # terrainlod_realdata takes the Jacksboro DEM out of its .npz
  libvips-tools imagemagick openimageio-tools   # anchors of tests/bench/resample_bench.sh only
  libqt5scxml5-dev           # Qt SCXML: the same-run anchor of tests/bench/bench_patnet_scxml
  draco                      # draco_encoder/draco_decoder: tests/bench/bench_ebm_vs_draco runs them as an anchor
  # tests/interop: independent readers of every format fest writes
  python3-vtk9               # VTK's own readers (PLY STL OBJ, VTK XML and legacy, MetaImage), from /usr/bin/python3
  teem-apps                  # teem-unu: NRRD's reference implementation
  openexr                    # exrheader
  gdal-bin                   # gdalinfo: TIFF; gdal_translate: meuse.tif as ASCII grid for tests/cli/terrainlod_nodata_realdata.sh
  python3-nibabel            # the independent volume reader of tests/cli/fconv_nibabel.sh; its test files are fetched as real data
  libopencv-contrib-dev libapriltag-dev   # cv::aruco and AprilTag 3: anchors of tests/bench/bench_markerpose only
  graphviz                   # dot: tests/cli/patnet.sh checks that `patnet dot` output is valid Graphviz
  libzfp-dev zfp libblosc-dev libzstd-dev zstd   # anchors of tests/bench/volwave.sh (bench_volwave links ZFP, Blosc, zstd)
  assimp-utils assimp-testmodels  # `assimp info`: independent mesh reader (tests/interop, fconv_assimp) and its test models
  libmeshoptimizer-dev libcgal-dev   # anchors of tests/bench/bench_decimate (meshopt_simplify, CGAL edge_collapse); built only when found
  netpbm openctm-tools hyperfine   # tests/bench/batch.sh and startup.sh only: netpbm and ctmconv anchors, hyperfine timings
  zzuf                       # tests/fuzz/mutate.sh: seeded bit-flip mutations of every input kind (run by hand)
  libjpeg-turbo-progs        # cjpeg/djpeg: independent JPEG encoder and decoder of tests/cli/resample_jpeg.sh
)

# --- arguments ----------------------------------------------------------------
with_test_tools=1
while [ $# -gt 0 ]; do
  case "$1" in
    --no-test-tools) with_test_tools=0 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "install-deps.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps.sh: run as root (or install sudo)" >&2; exit 1; fi
fi
export DEBIAN_FRONTEND=noninteractive


missing_pkgs() {  # prints the packages of "$@" that are not installed
  local p
  for p in "$@"; do
    dpkg-query -W -f='${db:Status-Status}\n' "$p" 2>/dev/null | grep -qx installed || echo "$p"
  done
}

# --- packages -----------------------------------------------------------------
wanted=("${BUILD_PKGS[@]}")
[ "$with_test_tools" -eq 1 ] && wanted+=("${TEST_TOOL_PKGS[@]}")
mapfile -t missing < <(missing_pkgs "${wanted[@]}")
if [ "${#missing[@]}" -gt 0 ]; then
  echo "install-deps.sh: installing ${#missing[@]} package(s): ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps.sh: all ${#wanted[@]} packages already installed"
fi
