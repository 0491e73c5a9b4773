# OpenCV's calibration (cv::calibrateCamera, cv::solve, cv::SVD) calls LAPACK and BLAS through
# libopencv_core. When ATLAS is installed (libceres3 brings it), Debian's alternatives make it
# liblapack.so.3 and libblas.so.3, and ATLAS's kernels sum in an order that depends on where a
# buffer lies in memory: the same chessboard views gave cameras that differed in the 13th digit
# between runs, and `eval court` moved a ball by up to 2 cm (docs/RESULTS.md, "Same seed, same
# figures"). Every program we build loads the reference LAPACK and BLAS (Debian's liblapack3 and
# libblas3) instead: it needs them first of all its libraries, found through its DT_RPATH, so
# that a later library asking for liblapack.so.3 or libblas.so.3 (libopencv_core; libcholmod,
# whose RUNPATH would skip our RPATH) gets the one already loaded, and that BLAS's symbols are
# found in them before ATLAS's own libf77blas (which Ceres links).
set(reference_dir /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE})
if(EXISTS ${reference_dir}/lapack/liblapack.so.3 AND EXISTS ${reference_dir}/blas/libblas.so.3)
  add_link_options(LINKER:--push-state,--no-as-needed ${reference_dir}/blas/libblas.so.3
                   ${reference_dir}/lapack/liblapack.so.3 LINKER:--pop-state
                   LINKER:--disable-new-dtags
                   LINKER:-rpath,${reference_dir}/lapack:${reference_dir}/blas)
else()
  message(WARNING "The reference LAPACK and BLAS (liblapack3, libblas3: ${reference_dir}/lapack, "
                  "${reference_dir}/blas) are not installed: with ATLAS or OpenBLAS, calibrated "
                  "cameras can differ in the last digits from run to run (scripts/setup installs "
                  "them)")
endif()
