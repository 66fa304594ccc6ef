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
# V4L2 cameras of capture (devices/v4l2_camera): OpenCV's VideoCapture with CAP_V4L2.
find_package(OpenCV 4 REQUIRED COMPONENTS videoio)
# capture calib-*: chessboard corners, Zhang's calibration, solvePnP (lib/capture calib).
find_package(OpenCV 4 REQUIRED COMPONENTS calib3d)
