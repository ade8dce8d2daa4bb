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

# A library found by its header and library file, as the imported target opgraph::<name>.
macro(_opgraph_find_by_hand name header library)
  find_path(_opgraph_${name}_include_dir ${header})
  find_library(_opgraph_${name}_library ${library})
  if(_opgraph_${name}_include_dir AND _opgraph_${name}_library)
    if(NOT TARGET opgraph::${name})
      add_library(opgraph::${name} UNKNOWN IMPORTED)
      set_target_properties(opgraph::${name} PROPERTIES
        IMPORTED_LOCATION "${_opgraph_${name}_library}"
        INTERFACE_INCLUDE_DIRECTORIES "${_opgraph_${name}_include_dir}")
    endif()
  elseif(_opgraph_as_package)
    list(APPEND _opgraph_missing ${name})
  else()
    message(FATAL_ERROR "${name} not found (${header}, lib${library})")
  endif()
endmacro()

# OpenSubdiv by hand: Debian's OpenSubdivConfig.cmake is broken.
_opgraph_find_by_hand(OpenSubdiv opensubdiv/far/topologyRefiner.h osdCPU)
# OpenMesh (the ops' half-edge connectivity, ops/halfedge_topology.h; Debian: libopenmesh-dev) by
# hand: its OpenMeshConfig.cmake has no version file and defines bare target names.
_opgraph_find_by_hand(OpenMesh OpenMesh/Core/Mesh/PolyConnectivity.hh OpenMeshCore)
