# The third-party packages behind opgraph's libraries, in one place for opgraph's own build
# (CMakeLists.txt: a missing one stops the configure) and for a consumer's find_package(opgraph)
# (opgraphConfig.cmake sets _opgraph_as_package: a missing one is added to _opgraph_missing, and
# opgraph is not found). The libraries are static, so whoever links them also needs what they
# link privately (Assimp, PCL, OpenSubdiv).

macro(_opgraph_find package)
  if(_opgraph_as_package)
    if(opgraph_FIND_QUIETLY)
      find_package(${package} ${ARGN} QUIET)
    else()
      find_package(${package} ${ARGN})
    endif()
    if(NOT ${package}_FOUND)
      list(APPEND _opgraph_missing ${package})
    endif()
  else()
    find_package(${package} ${ARGN} REQUIRED)
  endif()
endmacro()

_opgraph_find(Eigen3 NO_MODULE)
_opgraph_find(Ceres)
_opgraph_find(nlohmann_json)
_opgraph_find(CGAL)
_opgraph_find(assimp)

# Components only: a bare find_package(PCL) drags in VTK and Qt. VTK is kept out of the io
# component too: opgraph calls none of it (libpcl_io.so loads its own), and VTK's MPI target
# would need the C language enabled in every project that links opgraph::io.
set(_opgraph_vtk_was_disabled "${CMAKE_DISABLE_FIND_PACKAGE_VTK}")
set(CMAKE_DISABLE_FIND_PACKAGE_VTK TRUE)
_opgraph_find(PCL COMPONENTS common kdtree search features io)
if(NOT _opgraph_vtk_was_disabled)
  unset(CMAKE_DISABLE_FIND_PACKAGE_VTK)
endif()

# OpenSubdiv by hand: Debian's OpenSubdivConfig.cmake is broken.
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/far/topologyRefiner.h)
find_library(OPENSUBDIV_CPU_LIBRARY osdCPU)
if(OPENSUBDIV_INCLUDE_DIR AND OPENSUBDIV_CPU_LIBRARY)
  if(NOT TARGET opgraph::OpenSubdiv)
    add_library(opgraph::OpenSubdiv UNKNOWN IMPORTED)
    set_target_properties(opgraph::OpenSubdiv PROPERTIES
      IMPORTED_LOCATION "${OPENSUBDIV_CPU_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${OPENSUBDIV_INCLUDE_DIR}")
  endif()
elseif(_opgraph_as_package)
  list(APPEND _opgraph_missing OpenSubdiv)
else()
  message(FATAL_ERROR "OpenSubdiv not found (opensubdiv/far/topologyRefiner.h, libosdCPU)")
endif()
