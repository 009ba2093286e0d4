# Finds every dependency parcelflow builds against. Each one is a Debian package; when one is missing
# the message names the package to install (setup.sh installs them all).
include_guard(GLOBAL)

macro(parcelflow_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "parcelflow needs ${what}: install the Debian package '${package}' "
                        "(or run ./setup.sh, which installs every dependency).")
  endif()
endmacro()

find_package(MPI COMPONENTS C CXX QUIET)
parcelflow_require(MPI_CXX_FOUND "MPI" "libopenmpi-dev openmpi-bin")

find_package(Eigen3 3.3 NO_MODULE QUIET)
parcelflow_require(Eigen3_FOUND "Eigen 3" "libeigen3-dev")

find_package(yaml-cpp QUIET)
parcelflow_require(yaml-cpp_FOUND "yaml-cpp" "libyaml-cpp-dev")

find_package(GTest QUIET)
parcelflow_require(GTest_FOUND "GoogleTest" "libgtest-dev")

set(HDF5_PREFER_PARALLEL TRUE)
find_package(HDF5 COMPONENTS C QUIET)
parcelflow_require(HDF5_FOUND "HDF5" "libhdf5-openmpi-dev")
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "parcelflow needs the MPI-parallel HDF5 (found a serial one): install the Debian "
                      "package 'libhdf5-openmpi-dev'.")
endif()
add_library(parcelflow_hdf5 INTERFACE)
target_include_directories(parcelflow_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
target_link_libraries(parcelflow_hdf5 INTERFACE ${HDF5_C_LIBRARIES} MPI::MPI_C)
target_compile_definitions(parcelflow_hdf5 INTERFACE ${HDF5_C_DEFINITIONS})

find_path(METIS_INCLUDE_DIR metis.h)
find_library(METIS_LIBRARY metis)
parcelflow_require(METIS_LIBRARY "METIS" "libmetis-dev")
add_library(parcelflow_metis INTERFACE)
target_include_directories(parcelflow_metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(parcelflow_metis INTERFACE ${METIS_LIBRARY})

# hypre (BoomerAMG, the pressure preconditioner): Debian ships no pkg-config file for it, so look for
# the header and the library directly.
find_path(HYPRE_INCLUDE_DIR HYPRE.h PATH_SUFFIXES hypre)
find_library(HYPRE_LIBRARY HYPRE)
parcelflow_require(HYPRE_INCLUDE_DIR "hypre (BoomerAMG)" "libhypre-dev")
parcelflow_require(HYPRE_LIBRARY "hypre (BoomerAMG)" "libhypre-dev")
add_library(parcelflow_hypre INTERFACE)
target_include_directories(parcelflow_hypre SYSTEM INTERFACE ${HYPRE_INCLUDE_DIR})
target_link_libraries(parcelflow_hypre INTERFACE ${HYPRE_LIBRARY} MPI::MPI_C)

if(PARCELFLOW_WITH_LIGGGHTS)
  find_path(LIGGGHTS_INCLUDE_DIR lammps.h PATH_SUFFIXES liggghts)
  find_library(LIGGGHTS_LIBRARY liggghts)
  parcelflow_require(LIGGGHTS_LIBRARY "the LIGGGHTS library" "libliggghts-dev")
  find_program(LIGGGHTS_EXECUTABLE liggghts)
  parcelflow_require(LIGGGHTS_EXECUTABLE "the stock LIGGGHTS program (reference runs)" "liggghts")
  add_library(parcelflow_liggghts INTERFACE)
  target_include_directories(parcelflow_liggghts SYSTEM INTERFACE ${LIGGGHTS_INCLUDE_DIR})
  # Debian built LIGGGHTS with the default LAMMPS_SMALLBIG integer sizes; say so explicitly.
  target_compile_definitions(parcelflow_liggghts INTERFACE LAMMPS_SMALLBIG OMPI_SKIP_MPICXX)
  target_link_libraries(parcelflow_liggghts INTERFACE ${LIGGGHTS_LIBRARY} MPI::MPI_CXX)
endif()

# CGAL (header-only since 5.0; needs GMP and MPFR, which libcgal-dev pulls in): the cut-cell geometry's
# clipping and booleans (cfd/geometry/cut_cell_geometry.cpp; cfd/CMakeLists.txt keeps its compile options on
# those files). CGAL's config finds GMP and MPFR (libcgal-dev depends on libgmp-dev and libmpfr-dev).
find_package(CGAL 5.0 QUIET)
parcelflow_require(CGAL_FOUND "CGAL" "libcgal-dev")

find_program(MPIEXEC_EXECUTABLE NAMES mpirun mpiexec)
# Debian's python3 is the one that sees python3-numpy/-h5py/-matplotlib; prefer it over any other
# python3 earlier on PATH (pyenv and the like).
find_program(PARCELFLOW_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(PARCELFLOW_PYTHON python3)
parcelflow_require(PARCELFLOW_PYTHON "Python 3" "python3")
