# Every dependency comes from a Debian 12 -dev package (scripts/install-deps.sh).
# Quirks noted here were measured on that platform.
find_package(CLI11 CONFIG REQUIRED)
find_package(fmt CONFIG REQUIRED)
find_package(Eigen3 3.4 CONFIG REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(OpenMesh CONFIG REQUIRED)   # Debian ships no version file: no version here
find_package(draco CONFIG REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs)
# photo: CalibrateDebevec/MergeDebevec, the anchor of tests/bench/bench_hdrmerge only.
find_package(OpenCV 4 REQUIRED COMPONENTS photo)
find_package(OpenEXR 3 CONFIG REQUIRED)
find_package(ZLIB REQUIRED)
# Image codecs used directly by formats/image (not through OpenCV imgcodecs, whose
# dependencies would load ~140 shared libraries into every tool: issue 21).
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
find_package(TIFF 4.5 REQUIRED)
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel IOLegacy IOXML
  FiltersFlowPaths  # vtkStreamTracer: the anchor of tests/bench/bench_lemtrace
  FiltersCore RenderingCore RenderingVolume RenderingVolumeOpenGL2 RenderingOpenGL2)  # anchors of tests/bench/bench_isosurf, bench_volrender
find_package(PkgConfig REQUIRED)
pkg_check_modules(GPIOD  REQUIRED IMPORTED_TARGET libgpiod>=1.6)
pkg_check_modules(LIBUSB REQUIRED IMPORTED_TARGET libusb-1.0>=1.0.26)
find_package(Threads REQUIRED)
if(FEST_TESTS)
  find_package(GTest CONFIG REQUIRED)
  include(GoogleTest)
endif()
pkg_check_modules(MINIZIP REQUIRED IMPORTED_TARGET minizip)   # facefit: .npz (zip) model import

# ODE (libode-dev): only the lmfsim benchmark links it, as a same-run anchor (spec lmfsim §6).
pkg_check_modules(ODE IMPORTED_TARGET ode>=0.16)
set(FEST_ODE_FOUND ${ODE_FOUND})
# fluidsim: FFTW 3 for the fast Poisson/Helmholtz transforms, OpenMP for the parallel step.
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
find_package(OpenMP REQUIRED COMPONENTS CXX)
# terrainlod: DEMs through GDAL (GeoTIFF georeference, nodata, every raster GDAL reads).
find_package(GDAL CONFIG REQUIRED)
# SHA-256 checksums of capture sessions and of the mesh a lumitexel file belongs to
# (libssl-dev: OpenSSL's libcrypto).
find_package(OpenSSL REQUIRED COMPONENTS Crypto)
# V4L2 cameras of capture (devices/v4l2_camera) talk to the kernel through
# linux/videodev2.h (linux-libc-dev), not OpenCV's videoio, which maps ~240 shared
# libraries (ffmpeg, GStreamer...) at every start (issue 21).
# capture calib-*: chessboard corners, Zhang's calibration, solvePnP (lib/capture calib).
find_package(OpenCV 4 REQUIRED COMPONENTS calib3d)
# Volumes: NIfTI-1/-2 and Analyze headers through nifti_clib (libnifti2-dev). Debian 12's
# NIFTIConfig.cmake names /usr/lib/libznz.so.3.0.0, which is not where the library is, so
# the library is found directly.
find_path(NIFTI2_INCLUDE_DIR nifti2_io.h PATH_SUFFIXES nifti REQUIRED)
find_library(NIFTI2_LIBRARY nifti2 REQUIRED)
add_library(fest_nifti2 INTERFACE)
target_include_directories(fest_nifti2 SYSTEM INTERFACE ${NIFTI2_INCLUDE_DIR})
target_link_libraries(fest_nifti2 INTERFACE ${NIFTI2_LIBRARY})
# markerpose: the benchmark's anchors only (tests/bench/bench_markerpose): OpenCV's ArUco
# detector (libopencv-contrib-dev) and AprilTag 3 (libapriltag-dev). The tool itself needs
# neither; the benchmark is skipped when they are absent.
find_package(OpenCV 4 QUIET COMPONENTS aruco)
pkg_check_modules(APRILTAG IMPORTED_TARGET apriltag>=3)
