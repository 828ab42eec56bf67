# Finds what the OpenFOAM plugin (openfoam/) builds against: Debian's OpenFOAM libraries (packages
# openfoam, libopenfoam) and the source tree of the same version with its lnInclude folders, both
# installed by scripts/install_openfoam.sh. Sets FLUIDBED_OPENFOAM_FOUND, FLUIDBED_OPENFOAM_SOURCE
# (cache: the tree; default the newest /opt/fluidbed-openfoam/openfoam-*, or under the environment's
# FLUIDBED_OPENFOAM_SRC as the script takes it) and the libraries FLUIDBED_LIB_OPENFOAM,
# FLUIDBED_LIB_FINITE_VOLUME, FLUIDBED_LIB_INTERFACIAL. Included by the top-level CMakeLists.txt
# (to decide the default of FLUIDBED_BUILD_OPENFOAM) and by openfoam/CMakeLists.txt.
set(fluidbed_openfoam_cache /opt/fluidbed-openfoam)
if(DEFINED ENV{FLUIDBED_OPENFOAM_SRC})
  set(fluidbed_openfoam_cache $ENV{FLUIDBED_OPENFOAM_SRC})
endif()
file(GLOB fluidbed_openfoam_trees LIST_DIRECTORIES true ${fluidbed_openfoam_cache}/openfoam-*)
# Cached only once found, so that a build folder configured before the installation finds it later.
if(fluidbed_openfoam_trees)
  list(SORT fluidbed_openfoam_trees)
  list(POP_BACK fluidbed_openfoam_trees fluidbed_openfoam_newest)
  set(FLUIDBED_OPENFOAM_SOURCE "${fluidbed_openfoam_newest}" CACHE PATH
      "OpenFOAM source tree with lnInclude folders (scripts/install_openfoam.sh)")
endif()

find_library(FLUIDBED_LIB_OPENFOAM OpenFOAM)
find_library(FLUIDBED_LIB_FINITE_VOLUME finiteVolume)
find_library(FLUIDBED_LIB_INTERFACIAL compressibleEulerianInterfacialModels)
if(EXISTS "${FLUIDBED_OPENFOAM_SOURCE}/src/OpenFOAM/lnInclude" AND FLUIDBED_LIB_OPENFOAM
   AND FLUIDBED_LIB_FINITE_VOLUME AND FLUIDBED_LIB_INTERFACIAL)
  set(FLUIDBED_OPENFOAM_FOUND ON)
else()
  set(FLUIDBED_OPENFOAM_FOUND OFF)
endif()
